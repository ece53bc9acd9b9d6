#pragma once
// The scene's rules checked on the model itself, so an edit is validated
// without writing and re-reading the scene as JSON (issue 9). The JSON
// reader (scene/scene_json.cpp) applies the same functions to what it reads,
// and a test (tests/scene/model_validation_test.cpp) holds the two to the same
// problems on every scene of scenes/ with invalid values put in.

#include <set>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace sdfwb::scene {

// Remembers the verdicts of formula fields (parsing, and for polynomial nodes
// the exact expansion, can take milliseconds), so validating after each edit
// re-checks only the formulas that changed. Bounded: forgets everything when full.
class FormulaVerdicts {
public:
    std::string check(const FieldSpec& field, const FieldValue& value);

private:
    static constexpr std::size_t kMaxRemembered = 512;
    std::unordered_map<std::string, std::string> verdicts_;  // field range + text -> reason
};

// Problems of one node that need its children (their number) or several of its
// fields together, as (field or "children", reason).
std::vector<std::pair<std::string, std::string>> nodeStructureProblems(const KindSpec& spec, const Node& node);

// "" or the reason a scene cannot hold `count` lights.
std::string lightCountProblem(std::size_t count);

// "" or why the material at this place in the list cannot be named `name`
// (`seen` holds the names before it and receives this one).
std::string materialNameProblem(const std::string& name, std::set<std::string>& seen);

// "<path>.material: no material named ..." for every node (and the ground)
// naming a material the scene does not have; walks the tree without recursion.
std::vector<std::string> materialReferenceProblems(const Scene& scene);

// "<json path>: <reason>", the path shortened for one line as every scene problem is.
std::string problemAt(const std::string& path, const std::string& reason);

// The problems of the camera alone (a view change touches nothing else).
std::vector<std::string> cameraProblems(const Camera& camera);

// Every problem the JSON reader would report for this scene, each
// "<json path>: <reason>" (for values JSON cannot hold, such as NaN, a problem
// of their own); empty when the scene is valid.
std::vector<std::string> validateScene(const Scene& scene, FormulaVerdicts* verdicts = nullptr);

}  // namespace sdfwb::scene
