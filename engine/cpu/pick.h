#pragma once
// What a pixel shows: one primary ray traced on the CPU through the shared
// tracer (sdf/glsl/tracer.glsl, the code the GLSL backend runs, in float as
// the GLSL backend computes), and the primitive that decides the distance
// where it hits. Picking in the viewport, the pixel readout and the placement
// of new nodes all ask here, so a pick is the same whichever backend draws the
// image: both run this math, and this answer comes from the shared CPU path.
//
// The deciding primitive: the instructions are run one at a time through the
// CPU interpreter at the hit point, following which operand each boolean's
// result comes from (the nearer one of a union, the farther of an
// intersection, the cutter where a difference cuts, the larger side of a
// smooth blend). Primitives are numbered in the compiler's order, depth first
// through the scene tree (checked against the instruction list).

#include <optional>
#include <vector>

#include <glm/vec3.hpp>

#include "program/program.h"
#include "scene/scene.h"

namespace sdfwb::cpu {

struct PickResult {
    bool hit = false;          // the ray met a surface, the ground included
    int steps = 0;             // of the whole sample, as the step heat view counts them
    double t = 0;              // march distance of the hit along the unit ray
    glm::dvec3 position{0.0};  // world coordinates of the hit
    glm::dvec3 normal{0.0};    // world, unit: the field's gradient at the hit
    double distance = 0;       // the field's value at the hit
    bool ground = false;       // the deciding surface is the ground plane
    // Child indices from scene.root to the primitive deciding the distance;
    // nullopt for a miss or the ground.
    std::optional<std::vector<int>> node;
};

// Traces the ray through image point (x, y), in pixels from the top-left
// corner of the program's width x height image (a pixel's centre at +0.5).
// `program` must be compileScene(scene, ...) of this `scene`.
PickResult pickPixel(const scene::Scene& scene, const program::Program& program, double x, double y);

// The ray through the view centre, traced at the scene's own image size (its
// render.width x render.height): the hit epsilon is that of the pixels the
// user sees. (Through the corner of a 2 x 2 image the pixel epsilon is a fifth
// of the distance, and a ray passing 0.05 from a ball counted as meeting it.)
PickResult pickViewCentre(const scene::Scene& scene);

// The primitive deciding the field at a world point (nullopt: the ground, or
// no primitive at all).
std::optional<std::vector<int>> primitiveAt(const scene::Scene& scene, const program::Program& program,
                                            const glm::dvec3& world);

// The field (float, as rendered) and its unit gradient (double) at a world point.
double fieldDistance(const scene::Scene& scene, const program::Program& program, const glm::dvec3& world);
glm::dvec3 fieldNormal(const scene::Scene& scene, const program::Program& program, const glm::dvec3& world);

// Paths of the scene's drawn primitives in the compiler's order (depth first; hidden ones left out).
std::vector<std::vector<int>> primitivePaths(const scene::Node& root);

}  // namespace sdfwb::cpu
