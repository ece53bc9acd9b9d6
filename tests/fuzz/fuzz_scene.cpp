// Fuzz target: the scene loader. Any bytes either load or fail with
// SceneError; a scene that loads saves and reloads to the same scene.

#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "scene/scene_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sdfwb::scene;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    Scene scene;
    try {
        scene = parseScene(text);
    } catch (const SceneError& error) {
        if (error.problems().empty()) std::abort();
        return 0;
    }
    if (parseScene(serializeScene(scene)) != scene) std::abort();
    return 0;
}
