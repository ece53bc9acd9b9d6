#include "program/scene_images.h"

#include <stdexcept>

#include "image/encoding.h"
#include "scene/settings_table.h"
#include "sdf/shared.h"

namespace sdfwb::program {
namespace {

namespace shared = sdf::f64;

int environmentSide(int kind) { return kind == shared::ENVIRONMENT_BOX ? image::kMaxBoxFaceSide : image::kMaxEnvironmentSide; }

std::vector<std::filesystem::path> paths(const std::vector<std::string>& files) { return {files.begin(), files.end()}; }

image::PixelValues pixelValues(bool heights) { return heights ? image::PixelValues::Data : image::PixelValues::Colour; }

}  // namespace

std::filesystem::path sceneFilePath(const scene::Scene& scene, const std::string& name) {
    std::filesystem::path path(name);
    if (!path.is_absolute() && !scene.directory.path.empty()) {
        path = std::filesystem::path(scene.directory.path) / path;
    }
    return path.lexically_normal();
}

std::string sceneFileName(const scene::Scene& scene, const std::filesystem::path& file) {
    // "" is the working directory, which absolute() refuses to name
    const std::filesystem::path folder =
        scene.directory.path.empty() ? std::filesystem::current_path() : std::filesystem::absolute(scene.directory.path);
    const std::filesystem::path absolute = std::filesystem::absolute(file).lexically_normal();
    const std::filesystem::path relative = absolute.lexically_relative(folder.lexically_normal());
    return (relative.empty() ? absolute : relative).generic_string();
}

std::vector<SceneImageFile> environmentFiles(const scene::Scene& scene) {
    const scene::Environment& e = scene.environment;
    std::vector<SceneImageFile> files;
    auto add = [&](const char* key, const std::string& name) {
        files.push_back({std::string("environment.") + key, name, sceneFilePath(scene, name)});
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
    const int side = environmentSide(static_cast<int>(scene.environment.map));
    std::vector<SceneImageFile> files = environmentFiles(scene);
    std::vector<std::filesystem::path> all;
    for (const SceneImageFile& file : files) all.push_back(file.path);
    try {
        image::cachedMipmappedImages(all, side);  // what the render will ask for
        return problems;
    } catch (const std::exception&) {
        // find every file at fault, not only the first
    }
    for (const SceneImageFile& file : files) {
        if (file.name.empty()) {
            problems.push_back(file.key + ": the " +
                               scene::kEnvironmentMapNames[static_cast<int>(scene.environment.map)] +
                               " map needs an image file here");
            continue;
        }
        try {
            image::loadMipmappedImages({file.path}, 1);
        } catch (const std::exception& error) {
            problems.push_back(file.key + ": " + error.what());
        }
    }
    return problems;
}

std::vector<SceneImageFile> textureFiles(const scene::Scene& scene) {
    std::vector<SceneImageFile> files;
    for (std::size_t i = 0; i < scene.materials.size(); ++i) {
        const scene::Material& m = scene.materials[i];
        const std::string path = "materials[" + std::to_string(i) + "].";
        if (m.texture == scene::TexturePattern::Image)
            files.push_back({path + "texture_image", m.textureImage, sceneFilePath(scene, m.textureImage)});
        if (m.bump == scene::BumpPattern::Image)
            files.push_back(
                {path + "bump_image", m.bumpImage, sceneFilePath(scene, m.bumpImage), image::PixelValues::Data});
    }
    return files;
}

std::vector<std::string> textureProblems(const scene::Scene& scene) {
    std::vector<std::string> problems;
    for (const SceneImageFile& file : textureFiles(scene)) {
        if (file.name.empty()) {
            problems.push_back(file.key + ": an image " +
                               (file.values == image::PixelValues::Data ? "bump map" : "texture") +
                               " needs an image file here");
            continue;
        }
        try {
            image::cachedMipmappedImages({file.path}, image::kMaxTextureSide, file.values);
        } catch (const std::exception& error) {
            problems.push_back(file.key + ": " + error.what());
        }
    }
    return problems;
}

std::vector<std::string> sceneImageProblems(const scene::Scene& scene) {
    std::vector<std::string> problems = environmentProblems(scene);
    for (std::string& problem : textureProblems(scene)) problems.push_back(std::move(problem));
    return problems;
}

std::map<std::string, image::Image> sceneImagePreviews(const scene::Scene& scene, int maxSide) {
    std::map<std::string, image::Image> previews;
    // a set of files that cannot be read has no previews: the problems name the files at fault
    auto preview = [&](const std::vector<SceneImageFile>& files, int side) {
        std::vector<std::filesystem::path> all;
        for (const SceneImageFile& file : files) all.push_back(file.path);
        try {
            auto images = image::cachedMipmappedImages(all, side, files.front().values);
            for (std::size_t i = 0; i < files.size(); ++i) {
                image::Image thumbnail = image::mipmapPreview(*images, static_cast<int>(i), maxSide);
                // heights are shown as the file stores them: each value as
                // its display encoding, not as a linear colour
                if (files[i].values == image::PixelValues::Data)
                    for (float& value : thumbnail.rgb) value = image::linearFromSrgb(value);
                previews[files[i].key] = std::move(thumbnail);
            }
        } catch (const std::exception&) {
        }
    };
    std::vector<SceneImageFile> environment = environmentFiles(scene);
    if (!environment.empty()) preview(environment, environmentSide(static_cast<int>(scene.environment.map)));
    for (const SceneImageFile& file : textureFiles(scene)) preview({file}, image::kMaxTextureSide);
    return previews;
}

Program compileSceneReadingImages(const scene::Scene& scene, const CompileOptions& options) {
    Program program = compileScene(scene, options);
    resolveImages(program);
    return program;
}

void moveSceneDirectory(scene::Scene& scene, const std::filesystem::path& directory) {
    // "" is the working directory, which absolute() refuses to name
    const std::filesystem::path from = scene.directory.path.empty() ? std::filesystem::current_path()
                                                                    : std::filesystem::absolute(scene.directory.path);
    const std::filesystem::path to = std::filesystem::absolute(directory);
    auto rebase = [&](std::string& name) {
        if (name.empty() || std::filesystem::path(name).is_absolute()) return;
        std::filesystem::path moved = (from / name).lexically_normal().lexically_relative(to);
        if (!moved.empty()) name = moved.generic_string();
    };
    for (const scene::Setting<scene::Environment>& row : scene::environmentSettings()) {
        if (row.type == scene::SettingType::ImageFile) {
            rebase(scene.environment.*std::get<std::string scene::Environment::*>(row.member));
        }
    }
    for (scene::Material& m : scene.materials) {
        for (const scene::Setting<scene::Material>& row : scene::materialSettings()) {
            if (row.type == scene::SettingType::ImageFile)
                rebase(m.*std::get<std::string scene::Material::*>(row.member));
        }
    }
    scene.directory.path = to.string();
}

std::size_t ResolvedImages::textureStart(std::size_t file) const {
    std::size_t start = environment ? environment->texels.size() : 0;
    for (std::size_t i = 0; i < file; ++i) start += textures[i]->texels.size();
    return start;
}

ResolvedImages resolveImages(const Program& program) {
    ResolvedImages out;
    if (program.environmentKind != shared::ENVIRONMENT_COLOR) {
        try {
            out.environment =
                image::cachedMipmappedImages(paths(program.environmentFiles), environmentSide(program.environmentKind));
        } catch (const std::exception&) {
            out.environment = image::placeholderImages(static_cast<int>(program.environmentFiles.size()));
        }
        shared::EnvironmentMap map{program.environmentKind, out.environment->side, out.environment->levels,
                                   program.environmentIntensity};
        out.slots.emplace_back(shared::ENVIRONMENT_SLOT, shared::environmentSlot(map, 0));
    }
    for (const Program::TextureFile& file : program.textureFiles) {
        try {
            out.textures.push_back(
                image::cachedMipmappedImages({file.path}, image::kMaxTextureSide, pixelValues(file.heights)));
        } catch (const std::exception&) {
            out.textures.push_back(image::placeholderImages(1));
        }
    }
    for (const Program::TextureSlot& use : program.textureSlots) {
        const image::MipmappedImages& texture = *out.textures[static_cast<std::size_t>(use.file)];
        out.slots.emplace_back(use.slot,
                               glm::dvec4(static_cast<double>(out.textureStart(static_cast<std::size_t>(use.file))),
                                          texture.side, texture.levels, 0.0));
    }
    return out;
}

}  // namespace sdfwb::program
