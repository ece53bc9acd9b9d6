#pragma once
// The environment map's image files: which the scene names (resolved against
// its folder), whether they can be read, and the images themselves at render
// time, with the ENVIRONMENT_SLOT block that describes them to the shared
// sampler (sdf/glsl/environment_lookup.glsl). Both backends resolve a program's
// environment here, so they sample the same texels.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "image/environment_images.h"
#include "program/compile_scene.h"
#include "program/program.h"
#include "scene/scene.h"

namespace sdfwb::program {

struct EnvironmentFile {
    std::string key;   // JSON key under "environment"
    std::string name;  // as the scene names it; "" is a problem, not a file
    std::filesystem::path path;
};

// The files the scene's map reads, in the shared sampler's image order (the
// box map's faces +x -x +y -y +z -z); none for the background colour.
std::vector<EnvironmentFile> environmentFiles(const scene::Scene& scene);

// One line per file that cannot be used, "environment.<key>: cannot read
// image PATH: reason", or that is not given ("the box map needs an image
// file here": the editor lets a map be chosen before its files); reads the
// files (through a cache).
std::vector<std::string> environmentProblems(const scene::Scene& scene);

// compileScene, then the environment's images read into the cache on the
// calling thread: for callers that compile on a worker and render where a
// file read would stall (the window's UI thread, where the GL backend runs).
Program compileSceneReadingImages(const scene::Scene& scene, const CompileOptions& options);

// The scene as it will be saved in `directory`: relative file names that
// keep naming the same files from there, and `directory` set to it.
void moveSceneDirectory(scene::Scene& scene, const std::filesystem::path& directory);

struct ResolvedEnvironment {
    std::shared_ptr<const image::EnvironmentImages> images;  // null for the background colour
    glm::dvec4 slot{0.0};                                    // the ENVIRONMENT_SLOT block
};

// The program's environment images, read on first use; a map whose files
// cannot be read shows the marked placeholder (the editor reports why).
ResolvedEnvironment resolveEnvironment(const Program& program);

}  // namespace sdfwb::program
