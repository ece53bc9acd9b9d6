#pragma once
// The scene model: plain data, numbers as doubles, every field with a default.
// The JSON format is documented in docs/scene-format.md.

#include <iterator>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "scene/node_kinds.h"

namespace sdfwb::scene {

inline constexpr std::string_view kFormatTag = "sdf-workbench-scene";
inline constexpr int kFormatVersion = 1;

// How deep a node tree may nest, the root being level 1: generated scenes
// chain a thousand transforms; every tree walk is bounded by this.
inline constexpr int kMaxNodeDepth = 1024;

struct Node {
    NodeKind kind = NodeKind::Union;
    std::string name;
    std::vector<FieldValue> fields;  // one per kindSpec(kind).fields, in that order
    std::vector<Node> children;
    // Hide and solo (scene/visibility.h): a hidden node draws nothing; while
    // any node is soloed only soloed subtrees draw. Saved, and undoable.
    bool hidden = false;
    bool solo = false;

    bool operator==(const Node&) const = default;

    // A node of `kind` with every field at its default.
    static Node make(NodeKind kind);

    // Typed access by field name; the field must exist in the kind (checked).
    double real(std::string_view field) const;
    glm::dvec3 vec3(std::string_view field) const;
    const std::string& text(std::string_view field) const;
    void set(std::string_view field, FieldValue value);
};

// Orbit camera (thesis, section 2.1): the eye sits on a sphere around the target.
struct Camera {
    glm::dvec3 target{0.0, 0.5, 0.0};
    double azimuth = 30.0;    // degrees, about +y, 0 looks along -z
    double elevation = 20.0;  // degrees above the horizon, -90 to 90 (the frame stays valid at +-90)
    double distance = 6.0;    // from target to eye
    double fov = 45.0;        // vertical field of view, degrees

    bool operator==(const Camera&) const = default;
};

// Material textures (sdf/glsl/texture.glsl's TEXTURE_* codes, static_asserted in the compiler).
enum class TexturePattern { None, Checker, Stripes, Noise, Image };
inline constexpr const char* kTexturePatternNames[] = {"none", "checker", "stripes", "noise", "image"};
static_assert(std::size(kTexturePatternNames) == static_cast<size_t>(TexturePattern::Image) + 1);
// Distinct image files a scene's textures may name: with the environment's,
// their texels stay within 2^24, where a float still counts every texel.
inline constexpr int kMaxTextureImages = 16;
enum class BumpPattern { None, Noise, Waves, Image };
inline constexpr const char* kBumpPatternNames[] = {"none", "noise", "waves", "image"};
static_assert(std::size(kBumpPatternNames) == static_cast<size_t>(BumpPattern::Image) + 1);

struct Material {
    std::string name;
    glm::dvec3 ambient{0.05};   // R_A
    glm::dvec3 diffuse{0.7};    // R_D
    glm::dvec3 specular{0.3};   // R_E
    double shininess = 32.0;    // alpha
    glm::dvec3 emission{0.0};   // L_E
    double emissionStrength = 1.0;  // multiplies L_E
    // Ray tracing (lecture notes, section 2): secondary rays carry these
    // fractions of the light seen in the mirror direction and through the surface.
    double reflectivity = 0.0;            // k_ps, perfect-mirror fraction
    glm::dvec3 reflectionColor{1.0};      // M_PS
    double transparency = 0.0;            // k_t, transmitted fraction
    glm::dvec3 transmissionColor{1.0};    // M_T
    double ior = 1.5;                     // index of refraction (outside: 1)
    bool fresnel = false;                 // Schlick's weights instead of the notes' fixed k_ps, k_t
    // Colour texture (sdf/glsl/texture.glsl): a solid procedural pattern at
    // the object-space point mixes ambient and diffuse towards textureColor;
    // an image, at the primitive's (u, v), multiplies them.
    TexturePattern texture = TexturePattern::None;
    double textureScale = 0.25;  // cell, slab, noise feature or image tile size, object units
    glm::dvec3 textureColor{0.1};
    std::string textureImage;  // file, relative to the scene's folder
    bool textureSpecular = false;  // the texture modulates the specular colour R_E too
    bool textureFiltering = true;  // false: images read at full resolution only, patterns unfiltered
    // Bump map (sdf/glsl/texture.glsl): a height field of the object-space
    // point that perturbs the shading normal; the surface stays as it is.
    BumpPattern bump = BumpPattern::None;
    double bumpScale = 0.25;              // noise feature size or wavelength, or image tile size, object units
    double bumpDepth = 0.01;              // height of the field's range, object units
    std::string bumpImage;                // grey height map, relative to the scene's folder

    // A hit on it traces reflected or transmitted rays (within render.max_depth).
    bool mirrorOrGlass() const { return reflectivity > 0 || transparency > 0; }

    bool operator==(const Material&) const = default;
};

// Directional light.
struct Light {
    glm::dvec3 direction{0.5, 0.8, 0.3};  // towards the light; normalised when compiled
    glm::dvec3 color{1.0};                // S_i
    double softness = 8.0;                // k: 1.5 for a sun, 10 for a torch

    bool operator==(const Light&) const = default;
};

// Limits of the scene format, used by validation, the editor and the CLI.
inline constexpr int kMaxLights = 8;
inline constexpr int kMaxImageSize = 16384;  // pixels, width and height
inline constexpr int kMaxAa = 8;
inline constexpr int kMaxSteps = 8192;       // primary march
inline constexpr int kMaxShadowSteps = 4096;
inline constexpr int kMaxAoSamples = 64;
// Bounces of a ray tree (render.max_depth): up to 2^(d+1) - 1 rays per sample.
inline constexpr int kMaxTraceDepth = 6;

// Choices of the format, each with its JSON names in enum order. The shared
// tracer's codes (SHADOW_*, LIGHTING_*, GROUND_*) are checked against these
// enums in program/compile_scene.cpp.
enum class ShadowMode { None, Hard, Soft, Improved };
inline constexpr const char* kShadowModeNames[] = {"none", "hard", "soft", "improved"};
enum class LightingModel { BlinnPhong, Phong };
inline constexpr const char* kLightingModelNames[] = {"blinn_phong", "phong"};
enum class EpsilonMode { Absolute, Pixel };
inline constexpr const char* kEpsilonModeNames[] = {"absolute", "pixel"};
enum class GroundPattern { Plain, Checker, Grid };
inline constexpr const char* kGroundPatternNames[] = {"plain", "checker", "grid"};
// What the tracer uses besides the field: Bounded, the ground plane's exact
// distance along the ray (the march steps onto it) and the scene's bounds
// (a shadow ray ends once they show no sample can darken it); Plain, the
// field alone (plain sphere tracing, the speed report's baseline).
enum class Tracing { Bounded, Plain };
inline constexpr const char* kTracingNames[] = {"bounded", "plain"};
static_assert(std::size(kTracingNames) == static_cast<size_t>(Tracing::Plain) + 1);
static_assert(std::size(kShadowModeNames) == static_cast<size_t>(ShadowMode::Improved) + 1);
static_assert(std::size(kLightingModelNames) == static_cast<size_t>(LightingModel::Phong) + 1);
static_assert(std::size(kEpsilonModeNames) == static_cast<size_t>(EpsilonMode::Pixel) + 1);
static_assert(std::size(kGroundPatternNames) == static_cast<size_t>(GroundPattern::Grid) + 1);
enum class EnvironmentMapKind { Color, Equirect, Sphere, Box };
inline constexpr const char* kEnvironmentMapNames[] = {"color", "equirect", "sphere", "box"};
static_assert(std::size(kEnvironmentMapNames) == static_cast<size_t>(EnvironmentMapKind::Box) + 1);

struct RenderSettings {
    int width = 960;                 // pixels
    int height = 540;                // pixels
    int aa = 1;                      // AA x AA sub-samples per pixel, 1..8
    int maxSteps = 256;              // primary march
    double maxDistance = 100.0;      // scene units
    double epsilon = 1e-3;           // hit epsilon: scene units, or pixels in Pixel mode
    EpsilonMode epsilonMode = EpsilonMode::Absolute;
    ShadowMode shadows = ShadowMode::Soft;
    int shadowSteps = 64;
    int aoSamples = 0;               // M; 0 disables ambient occlusion
    double aoDistance = 1.0;         // scene units covered by the AO samples
    LightingModel lighting = LightingModel::BlinnPhong;
    double exposure = 1.0;           // multiplies the final linear colour
    double stepRelaxation = 1.0;     // omega of over-relaxed primary steps, 1 to 1.9; 1 is plain sphere tracing
    Tracing tracing = Tracing::Bounded;
    int maxDepth = 4;                // bounces of reflected and refracted rays, 0 to kMaxTraceDepth
    double rayWeightCutoff = 1.0 / 256.0;  // secondary rays weighing less (every channel) are not traced

    bool operator==(const RenderSettings&) const = default;
};

struct Ground {
    bool enabled = false;
    double height = 0.0;             // the plane y = height
    std::string material;            // "" = the default material
    GroundPattern pattern = GroundPattern::Checker;
    double cellSize = 1.0;           // scene units
    double lineWidth = 0.04;         // scene units, grid pattern
    glm::dvec3 secondColor{0.25};    // colour of alternate cells or grid lines

    bool operator==(const Ground&) const = default;
};

// The environment map (lecture notes on realism, 1.5): what rays that leave
// the scene see. Image paths are relative to the scene file's folder.
struct Environment {
    glm::dvec3 ambient{0.03};               // L_A
    glm::dvec3 background{0.55, 0.65, 0.8};
    EnvironmentMapKind map = EnvironmentMapKind::Color;
    std::string image;                      // equirect and sphere maps
    std::string boxPositiveX, boxNegativeX, boxPositiveY, boxNegativeY, boxPositiveZ, boxNegativeZ;
    double intensity = 1.0;                 // multiplies the images' radiance
    Ground ground;

    bool operator==(const Environment&) const = default;
};

// The folder that relative file names in a scene (environment images)
// resolve against: its file's, set where a file is read or saved; "" is the
// working directory. Not part of the JSON, so not of the scene's value: two
// scenes equal as documents are equal wherever they were read.
struct SceneDirectory {
    std::string path;
    bool operator==(const SceneDirectory&) const { return true; }
};

struct Scene {
    std::string name = "untitled";
    std::string description;
    Camera camera;
    RenderSettings render;
    Environment environment;
    std::vector<Light> lights{Light{}};
    std::vector<Material> materials;
    Node root = Node::make(NodeKind::Union);
    SceneDirectory directory;

    bool operator==(const Scene&) const = default;

    // nullptr when no material has that name.
    const Material* findMaterial(std::string_view name) const;
    // Whether some material reflects or transmits: only then does the ray
    // tree trace secondary rays.
    bool hasMirrorsOrGlass() const;
};

// The material used where a primitive names none ("").
Material defaultMaterial();

// Levels of the tree under `node`, itself being level 1; without recursion, so
// it also measures trees deeper than kMaxNodeDepth (an edit can build one).
int treeDepth(const Node& node);

}  // namespace sdfwb::scene
