#pragma once
// The scene's image files: the environment map's (lecture notes on realism,
// 1.5) and the materials' image textures (1.1). Which files the scene names
// (resolved against its folder), whether they can be read, and the images
// themselves at render time, with the parameter slots that describe them to
// the shared sampler (sdf/glsl/mipmap_lookup.glsl). Both backends resolve a
// program's images here, so they sample the same texels.

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <glm/vec4.hpp>

#include "image/mipmapped_images.h"
#include "program/compile_scene.h"
#include "program/program.h"
#include "scene/scene.h"

namespace sdfwb::program {

struct SceneImageFile {
    std::string key;   // JSON path of the field that names it: "environment.box_px", "materials[2].texture_image"
    std::string name;  // as the scene names it; "" is a problem, not a file
    std::filesystem::path path;
    image::PixelValues values = image::PixelValues::Colour;  // a bump map's are data (heights)
};

// The files the scene's map reads, in the shared sampler's image order (the
// box map's faces +x -x +y -y +z -z); none for the background colour.
std::vector<SceneImageFile> environmentFiles(const scene::Scene& scene);

// One file per material whose texture is an image and one per material whose
// bump map is, in material order (a material's texture before its bump map).
std::vector<SceneImageFile> textureFiles(const scene::Scene& scene);

// One line per file that cannot be used, "environment.<key>: cannot read
// image PATH: reason" or "materials[i].texture_image: ...", or that is not
// given ("the box map needs an image file here": the editor lets a map or a
// texture be chosen before its files); reads the files (through a cache).
std::vector<std::string> environmentProblems(const scene::Scene& scene);
std::vector<std::string> textureProblems(const scene::Scene& scene);
std::vector<std::string> sceneImageProblems(const scene::Scene& scene);

// A thumbnail (image::mipmapPreview, side at most `maxSide`) of each file
// that can be read, by its key; read through the cache, as a render would.
std::map<std::string, image::Image> sceneImagePreviews(const scene::Scene& scene, int maxSide);

// compileScene, then the scene's images read into the cache on the calling
// thread: for callers that compile on a worker and render where a file read
// would stall (the window's UI thread, where the GL backend runs).
Program compileSceneReadingImages(const scene::Scene& scene, const CompileOptions& options);

// The scene as it will be saved in `directory`: relative file names that
// keep naming the same files from there, and `directory` set to it.
void moveSceneDirectory(scene::Scene& scene, const std::filesystem::path& directory);

// `name` as the scene names a file, resolved against its folder.
std::filesystem::path sceneFilePath(const scene::Scene& scene, const std::string& name);
// The other way: how the scene names `file` (an image picked in the editor),
// relative to its folder, or absolute where no relative name reaches it.
std::string sceneFileName(const scene::Scene& scene, const std::filesystem::path& file);

struct ResolvedImages {
    // The texel buffer: the environment's images (if any), then each texture file's.
    std::shared_ptr<const image::MipmappedImages> environment;  // null for the background colour
    std::vector<std::shared_ptr<const image::MipmappedImages>> textures;
    // Parameter slots to fill: ENVIRONMENT_SLOT, and each ImageTexture's image slot.
    std::vector<std::pair<int, glm::dvec4>> slots;

    bool any() const { return environment != nullptr || !textures.empty(); }
    // Texels before texture file i's (the environment's and earlier textures').
    std::size_t textureStart(std::size_t file) const;
};

// The program's images, read on first use; a map or texture whose files
// cannot be read shows the marked placeholder (the editor reports why).
ResolvedImages resolveImages(const Program& program);

}  // namespace sdfwb::program
