#include "program/environment.h"

#include <stdexcept>

#include "scene/settings_table.h"
#include "sdf/shared.h"

namespace sdfwb::program {
namespace {

namespace shared = sdf::f64;

int maxSide(int kind) { return kind == shared::ENVIRONMENT_BOX ? image::kMaxBoxFaceSide : image::kMaxEnvironmentSide; }

std::vector<std::filesystem::path> paths(const std::vector<std::string>& files) { return {files.begin(), files.end()}; }

}  // namespace

std::vector<EnvironmentFile> environmentFiles(const scene::Scene& scene) {
    const scene::Environment& e = scene.environment;
    std::vector<EnvironmentFile> files;
    auto add = [&](const char* key, const std::string& name) {
        std::filesystem::path path(name);
        if (!path.is_absolute() && !scene.directory.path.empty()) {
            path = std::filesystem::path(scene.directory.path) / path;
        }
        files.push_back({key, name, path.lexically_normal()});
    };
    switch (e.map) {
    case scene::EnvironmentMapKind::Color: break;
    case scene::EnvironmentMapKind::Equirect:
    case scene::EnvironmentMapKind::Sphere: add("image", e.image); break;
    case scene::EnvironmentMapKind::Box:
        add("box_px", e.boxPositiveX);
        add("box_nx", e.boxNegativeX);
        add("box_py", e.boxPositiveY);
        add("box_ny", e.boxNegativeY);
        add("box_pz", e.boxPositiveZ);
        add("box_nz", e.boxNegativeZ);
        break;
    }
    return files;
}

std::vector<std::string> environmentProblems(const scene::Scene& scene) {
    std::vector<std::string> problems;
    const int side = maxSide(static_cast<int>(scene.environment.map));
    std::vector<EnvironmentFile> files = environmentFiles(scene);
    std::vector<std::filesystem::path> all;
    for (const EnvironmentFile& file : files) all.push_back(file.path);
    try {
        image::cachedEnvironmentImages(all, side);  // what the render will ask for
        return problems;
    } catch (const std::exception&) {
        // find every file at fault, not only the first
    }
    for (const EnvironmentFile& file : files) {
        if (file.name.empty()) {
            problems.push_back("environment." + file.key + ": the " +
                               scene::kEnvironmentMapNames[static_cast<int>(scene.environment.map)] +
                               " map needs an image file here");
            continue;
        }
        try {
            image::loadEnvironmentImages({file.path}, 1);
        } catch (const std::exception& error) {
            problems.push_back("environment." + file.key + ": " + error.what());
        }
    }
    return problems;
}

Program compileSceneReadingImages(const scene::Scene& scene, const CompileOptions& options) {
    Program program = compileScene(scene, options);
    resolveEnvironment(program);
    return program;
}

void moveSceneDirectory(scene::Scene& scene, const std::filesystem::path& directory) {
    // "" is the working directory, which absolute() refuses to name
    const std::filesystem::path from = scene.directory.path.empty() ? std::filesystem::current_path()
                                                                    : std::filesystem::absolute(scene.directory.path);
    const std::filesystem::path to = std::filesystem::absolute(directory);
    for (const scene::Setting<scene::Environment>& row : scene::environmentSettings()) {
        if (row.type != scene::SettingType::Text) continue;
        std::string& name = scene.environment.*std::get<std::string scene::Environment::*>(row.member);
        if (name.empty() || std::filesystem::path(name).is_absolute()) continue;
        std::filesystem::path moved = (from / name).lexically_normal().lexically_relative(to);
        if (!moved.empty()) name = moved.generic_string();
    }
    scene.directory.path = to.string();
}

ResolvedEnvironment resolveEnvironment(const Program& program) {
    ResolvedEnvironment out;
    if (program.environmentKind == shared::ENVIRONMENT_COLOR) return out;
    try {
        out.images = image::cachedEnvironmentImages(paths(program.environmentFiles), maxSide(program.environmentKind));
    } catch (const std::exception&) {
        out.images = image::placeholderEnvironmentImages(static_cast<int>(program.environmentFiles.size()));
    }
    shared::EnvironmentMap map{program.environmentKind, out.images->side, out.images->levels,
                               program.environmentIntensity};
    out.slot = shared::environmentSlot(map, 0);
    return out;
}

}  // namespace sdfwb::program
