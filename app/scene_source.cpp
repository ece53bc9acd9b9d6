#include "app/scene_source.h"

#include <filesystem>

#include "scene/scene_json.h"

namespace sdfwb::app {

scene::Scene loadSceneArgument(const std::string& argument) {
    if (argument.empty() || (argument == "default" && !std::filesystem::exists(argument))) {
        return scene::parseScene(defaultSceneJson());
    }
    return scene::loadSceneFile(argument);
}

}  // namespace sdfwb::app
