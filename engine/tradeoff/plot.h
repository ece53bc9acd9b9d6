#pragma once
// A scene's time-against-error plot (PLplot, PNG through its cairo driver): every
// measured setting per backend, each backend's Pareto front drawn, the scene's
// default marked, the 1/255 tolerance as a dashed line; log scales.

#include <filesystem>

#include "tradeoff/sweep.h"

namespace sdfwb::tradeoff {

// Writes atomically. Throws std::runtime_error naming the path when PLplot
// cannot make the file.
void plotScene(const SceneResult& scene, const std::vector<std::string>& backends, const std::filesystem::path& png);

}  // namespace sdfwb::tradeoff
