#include "app/command_errors.h"

#include <iostream>
#include <new>

#include "scene/scene_json.h"

namespace sdfwb::app {

int runReportingErrors(const char* command, const std::function<int()>& body) {
    try {
        return body();
    } catch (const scene::SceneError& error) {
        for (const std::string& problem : error.problems()) {
            std::cerr << "sdf-workbench " << command << ": " << problem << "\n";
        }
    } catch (const std::bad_alloc&) {
        std::cerr << "sdf-workbench " << command << ": out of memory\n";
    } catch (const std::exception& error) {
        std::cerr << "sdf-workbench " << command << ": " << error.what() << "\n";
    }
    return kExitError;
}

}  // namespace sdfwb::app
