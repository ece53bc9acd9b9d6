#pragma once
// The edit layer: the scene being edited, every change to it as an undoable
// step, and the selection. The UI panels, the viewport's camera and the script
// interpreter all edit through it, so undo works the same for each.
//
// Every edit is checked with the scene loader's rules before it is applied; a
// rejected edit leaves the scene unchanged and returns the loader's messages
// ("root.children[0].radius: must be > 0 (got -1)"). So the edited scene is
// always one that sceneFromJson would accept, and always compiles.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/scene.h"
#include "scene/scene_validation.h"
#include "ui/node_path.h"

namespace sdfwb::ui {

// Why an edit was refused, one line per problem; empty when it was applied.
using Problems = std::vector<std::string>;

class Editor {
public:
    explicit Editor(scene::Scene scene = {});

    const scene::Scene& scene() const { return scene_; }
    // Changes with every applied edit, undo, redo and reset: the viewport
    // re-renders when it differs from what it last rendered.
    std::uint64_t revision() const { return revision_; }

    // --- Selection (not part of the scene; undo restores it with the scene) ---
    const std::optional<NodePath>& selection() const { return selection_; }
    // Ignores a path that leads nowhere (clears the selection instead).
    void select(std::optional<NodePath> path);
    const scene::Node* selectedNode() const;

    // --- The general edit ---
    // Applies `change` to a copy of the scene, validates the result and commits
    // it as one undo step named `label`. Consecutive edits with the same
    // non-empty `mergeKey` become one step until endMerge() (a slider drag).
    Problems apply(std::string_view label, const std::function<void(scene::Scene&)>& change,
                   std::string_view mergeKey = {});
    // Closes the open merge: the next edit starts a new undo step.
    void endMerge() { mergeOpen_ = false; }

    // --- The view (not an edit) ---
    // Moves the camera without an undo step and without marking the document
    // modified (the camera is still saved with the scene); undo and redo keep
    // the current view. Refused, with the loader's words, for a camera the
    // loader would not accept (distance <= 0, a field of view out of range).
    Problems setView(const scene::Camera& camera);
    // Sets the folder the scene's relative file names resolve against (its
    // file's, when opened or saved): likewise not an edit, kept by undo and redo.
    void setDirectory(std::string directory);

    // --- Node edits (paths are JSON node paths) ---
    Problems setField(const NodePath& path, std::string_view field, scene::FieldValue value,
                      std::string_view mergeKey = {});
    Problems rename(const NodePath& path, std::string name);
    // Hide and solo (scene/visibility.h): saved with the scene, undoable.
    Problems setHidden(const NodePath& path, bool hidden);
    Problems setSolo(const NodePath& path, bool solo);
    // Inserts `node` as child `index` of `parent` (-1: last) and selects it;
    // the undo step is `label`, or "Add <kind>" when empty.
    Problems insert(const NodePath& parent, int index, scene::Node node, std::string_view label = {});
    // The parent and index add() would insert at (nullopt: `under` leads nowhere).
    std::optional<std::pair<NodePath, int>> insertionPoint(const std::optional<NodePath>& under) const;
    // Where `add <kind>` puts a node: into `under` (default: the selection)
    // if it takes one more child, otherwise next to it in its parent; the root
    // when nothing fits. An operator that needs a child wraps `under` instead.
    Problems add(scene::NodeKind kind, const std::optional<NodePath>& under);
    // Puts `node` (which needs no child) where add() would put its kind.
    Problems add(scene::Node node, const std::optional<NodePath>& under);
    // Replaces the node by a new `kind` node holding it; selects the new node.
    Problems wrap(const NodePath& path, scene::NodeKind kind);
    // Moves the subtree to child `index` of `newParent` (index counted in the
    // parent as it is before the move); reparent and reorder alike.
    Problems move(const NodePath& from, const NodePath& newParent, int index);
    Problems duplicate(const NodePath& path);
    // Deletes the subtree and every wrapper it leaves without its one child
    // (a translate around a deleted sphere), in one undo step; selects what
    // held the topmost node removed.
    Problems remove(const NodePath& path);

    // Replaces the value at a JSON path of the scene file ("render.aa",
    // "lights[0].softness", "root.children[0].radius") and validates the whole
    // scene as the loader does.
    Problems setJsonValue(std::string_view jsonPath, const nlohmann::ordered_json& value,
                          std::string_view mergeKey = {});

    // --- History ---
    bool canUndo() const { return !undo_.empty(); }
    bool canRedo() const { return !redo_.empty(); }
    // Label of the step undo()/redo() would take back or replay ("" if none).
    std::string_view undoLabel() const;
    std::string_view redoLabel() const;
    bool undo();
    bool redo();

    // --- Documents ---
    // A new document (New, Open): clears history and selection, not dirty.
    void reset(scene::Scene scene);
    // Whether the scene differs from the last saved (or reset) state.
    bool dirty() const { return stateId_ != savedStateId_; }
    void markSaved() { savedStateId_ = stateId_; }

private:
    struct Step {
        scene::Scene scene;
        std::optional<NodePath> selection;
        std::string label;
        std::string mergeKey;
        std::uint64_t stateId;
    };
    Problems commit(std::string_view label, scene::Scene candidate, std::optional<NodePath> selection,
                    std::string_view mergeKey);
    void restore(Step& from, std::vector<Step>& to);

    scene::Scene scene_;
    std::optional<NodePath> selection_;
    std::vector<Step> undo_;
    std::vector<Step> redo_;
    bool mergeOpen_ = false;
    std::uint64_t revision_ = 1;
    std::uint64_t stateId_ = 1;
    std::uint64_t nextStateId_ = 2;
    std::uint64_t savedStateId_ = 1;
    scene::FormulaVerdicts formulaVerdicts_;  // every commit validates the whole scene
};

}  // namespace sdfwb::ui
