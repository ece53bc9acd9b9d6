#include "scene/settings_table.h"

namespace sdfwb::scene {
namespace {

using enum SettingType;
using enum RealRange;

const Setting<Camera> kCamera[] = {
    {"target", "target", "", Vector, &Camera::target},
    {"azimuth", "azimuth", "degrees", Real, &Camera::azimuth},
    {"elevation", "elevation", "degrees", Real, &Camera::elevation, Closed, -90, 90},
    {"distance", "distance", "units", Real, &Camera::distance, Positive},
    {"fov", "field of view", "degrees", Real, &Camera::fov, Open, 0, 180},
};

const Setting<RenderSettings> kRender[] = {
    {"width", "snapshot width", "pixels", Integer, &RenderSettings::width, Any, 1, kMaxImageSize, {}, {1.0}},
    {"height", "snapshot height", "pixels", Integer, &RenderSettings::height, Any, 1, kMaxImageSize, {}, {1.0}},
    {"aa", "AA level", "", Integer, &RenderSettings::aa, Any, 1, kMaxAa, {}, {0.05}},
    {"max_steps", "max steps", "", Integer, &RenderSettings::maxSteps, Any, 1, kMaxSteps, {}, {1.0}},
    {"max_distance", "max distance", "units", Real, &RenderSettings::maxDistance, Positive, 0, 0, {},
     {0.5, 1e-3, 1e9}},
    // the editor drags epsilon by 0.01 in pixel mode (settings_panels.cpp)
    {"epsilon", "epsilon", "", Real, &RenderSettings::epsilon, Positive, 0, 0, {}, {1e-5, 1e-9, 1e6, "%.5g"}},
    {"epsilon_mode", "epsilon mode", "", Choice, choiceMember<&RenderSettings::epsilonMode>(), Any, 0, 0,
     kEpsilonModeNames},
    {"shadows", "shadows", "", Choice, choiceMember<&RenderSettings::shadows>(), Any, 0, 0, kShadowModeNames},
    {"shadow_steps", "shadow steps", "", Integer, &RenderSettings::shadowSteps, Any, 1, kMaxShadowSteps, {}, {0.5}},
    {"ao_samples", "AO samples", "", Integer, &RenderSettings::aoSamples, Any, 0, kMaxAoSamples, {}, {0.1}},
    {"ao_distance", "AO distance", "units", Real, &RenderSettings::aoDistance, Positive, 0, 0, {}, {0.01, 1e-4, 1e6}},
    {"lighting", "lighting", "", Choice, choiceMember<&RenderSettings::lighting>(), Any, 0, 0, kLightingModelNames},
    {"step_relaxation", "step relaxation", "", Real, &RenderSettings::stepRelaxation, Closed, 1, 1.9, {},
     {0.01, 1, 1.9, "%.3f", EditorSection::Quality}},
    {"tracing", "tracing", "", Choice, choiceMember<&RenderSettings::tracing>(), Any, 0, 0, kTracingNames},
    {"exposure", "exposure", "", Real, &RenderSettings::exposure, Positive, 0, 0, {}, {0.01, 1e-3, 1e3}},
    {"max_depth", "recursion depth", "", Integer, &RenderSettings::maxDepth, Any, 0, kMaxTraceDepth, {}, {0.05}},
    {"ray_weight_cutoff", "ray weight cutoff", "", Real, &RenderSettings::rayWeightCutoff, Closed, 0, 1, {},
     {0.001, 0, 1, "%.4f"}},
};

const Setting<Environment> kEnvironment[] = {
    {"ambient", "ambient light", "", Colour, &Environment::ambient},
    {"background", "background", "", Colour, &Environment::background},
    {"map", "environment map", "", Choice, choiceMember<&Environment::map>(), Any, 0, 0, kEnvironmentMapNames},
    {"image", "image", "", ImageFile, &Environment::image},
    {"box_px", "box +x face", "", ImageFile, &Environment::boxPositiveX},
    {"box_nx", "box -x face", "", ImageFile, &Environment::boxNegativeX},
    {"box_py", "box +y face", "", ImageFile, &Environment::boxPositiveY},
    {"box_ny", "box -y face", "", ImageFile, &Environment::boxNegativeY},
    {"box_pz", "box +z face", "", ImageFile, &Environment::boxPositiveZ},
    {"box_nz", "box -z face", "", ImageFile, &Environment::boxNegativeZ},
    {"intensity", "map intensity", "", Real, &Environment::intensity, Closed, 0, 1e6, {}, {0.01, 0.0, 1e6}},
};

const Setting<Ground> kGround[] = {
    {"enabled", "enabled", "", Flag, &Ground::enabled},
    {"height", "height", "units", Real, &Ground::height, Any, 0, 0, {}, {0.01, -1e6, 1e6}},
    {"material", "material", "", Text, &Ground::material},
    {"pattern", "pattern", "", Choice, choiceMember<&Ground::pattern>(), Any, 0, 0, kGroundPatternNames},
    {"cell_size", "cell size", "units", Real, &Ground::cellSize, Positive, 0, 0, {}, {0.01, 1e-4, 1e6}},
    {"line_width", "line width", "units", Real, &Ground::lineWidth, NonNegative, 0, 0, {}, {0.001, 0.0, 1e6}},
    {"second_color", "second colour", "", Colour, &Ground::secondColor},
};

const Setting<Light> kLight[] = {
    {"direction", "direction", "", Direction, &Light::direction},
    {"color", "colour", "", Colour, &Light::color},
    {"softness", "softness k", "", Real, &Light::softness, Positive, 0, 0, {}, {0.05, 0.01, 1000.0, "%.2f"}},
};

const Setting<Material> kMaterial[] = {
    {"name", "name", "", Text, &Material::name},
    {"ambient", "ambient", "", Colour, &Material::ambient},
    {"diffuse", "diffuse", "", Colour, &Material::diffuse},
    {"specular", "specular", "", Colour, &Material::specular},
    {"shininess", "shininess", "", Real, &Material::shininess, Positive, 0, 0, {}, {0.5, 0.1, 4096.0, "%.1f"}},
    {"emission", "emission", "", Colour, &Material::emission},
    {"emission_strength",
     "emission strength",
     "",
     Real,
     &Material::emissionStrength,
     NonNegative,
     0,
     0,
     {},
     {0.01, 0.0, 1e3}},
    {"reflectivity", "mirror k_ps", "", Real, &Material::reflectivity, Closed, 0, 1, {}, {0.005, 0, 1}},
    {"reflection_color", "mirror colour M_PS", "", Colour, &Material::reflectionColor},
    {"transparency", "transmission k_t", "", Real, &Material::transparency, Closed, 0, 1, {}, {0.005, 0, 1}},
    {"transmission_color", "transmission colour M_T", "", Colour, &Material::transmissionColor},
    {"ior", "index of refraction", "", Real, &Material::ior, Closed, 0.2, 4, {}, {0.005, 0.2, 4}},
    {"fresnel", "Fresnel (Schlick)", "", Flag, &Material::fresnel},
    {"texture", "texture", "", Choice, choiceMember<&Material::texture>(), Any, 0, 0, kTexturePatternNames},
    {"texture_scale",
     "texture scale",
     "",
     Real,
     &Material::textureScale,
     Closed,
     1e-4,
     1e4,
     {},
     {0.005, 1e-4, 1e4, "%.3f"}},
    {"texture_color", "texture colour", "", Colour, &Material::textureColor},
    {"texture_image", "texture image", "", ImageFile, &Material::textureImage},
    {"texture_specular", "texture on specular", "", Flag, &Material::textureSpecular},
    {"texture_filtering", "texture filtering", "", Flag, &Material::textureFiltering},
    {"bump", "bump map", "", Choice, choiceMember<&Material::bump>(), Any, 0, 0, kBumpPatternNames},
    {"bump_scale", "bump scale", "", Real, &Material::bumpScale, Closed, 1e-4, 1e4, {}, {0.005, 1e-4, 1e4, "%.3f"}},
    {"bump_depth", "bump depth", "", Real, &Material::bumpDepth, Closed, 0, 1e3, {}, {0.001, 0, 1e3, "%.4f"}},
    {"bump_image", "bump image", "", ImageFile, &Material::bumpImage},
};

}  // namespace

std::span<const Setting<Camera>> cameraSettings() { return kCamera; }
std::span<const Setting<RenderSettings>> renderSettings() { return kRender; }
std::span<const Setting<Environment>> environmentSettings() { return kEnvironment; }
std::span<const Setting<Ground>> groundSettings() { return kGround; }
std::span<const Setting<Light>> lightSettings() { return kLight; }
std::span<const Setting<Material>> materialSettings() { return kMaterial; }

}  // namespace sdfwb::scene
