#pragma once
// The scene's settings tables: one row per JSON key of the camera, render,
// environment, ground, light and material objects, with the struct member it
// fills, its range, unit and editor label. JSON reading and writing, their
// validation, the editor's widgets and docs/adding-a-setting.md's checks all
// come from these rows; nothing else types a key or a range.

#include <span>
#include <string>
#include <string_view>
#include <variant>

#include <glm/vec3.hpp>

#include "scene/scene.h"

namespace sdfwb::scene {

// An enum member seen as its index into the row's choices.
template <typename Owner>
struct ChoiceMember {
    int (*get)(const Owner&);
    void (*set)(Owner&, int);
};

template <auto Member>
struct EnumAccess;
template <typename O, typename Enum, Enum O::*Member>
struct EnumAccess<Member> {
    using Owner = O;
    static int get(const O& o) { return static_cast<int>(o.*Member); }
    static void set(O& o, int v) { o.*Member = static_cast<Enum>(v); }
};
// choiceMember<&RenderSettings::shadows>()
template <auto Member>
constexpr ChoiceMember<typename EnumAccess<Member>::Owner> choiceMember() {
    return {&EnumAccess<Member>::get, &EnumAccess<Member>::set};
}

enum class SettingType {
    Integer,    // int, from minimum to maximum
    Real,       // double, see RealRange
    Choice,     // an enum, by name from `choices`
    Colour,     // glm::dvec3, every component >= 0
    Vector,     // glm::dvec3, any
    Direction,  // glm::dvec3, not zero
    Flag,       // bool
    Text,       // std::string
    ImageFile,  // std::string: an image file's name, relative to the scene file's folder
};

enum class RealRange {
    Any,
    Positive,     // > 0
    NonNegative,  // >= 0
    Closed,       // minimum to maximum
    Open,         // strictly between minimum and maximum
};

template <typename Owner>
using SettingMember = std::variant<int Owner::*, double Owner::*, glm::dvec3 Owner::*, bool Owner::*,
                                   std::string Owner::*, ChoiceMember<Owner>>;

// Where the editor draws a row: its object's panel, or the render panel's
// quality section beside the presets that set it (ui/quality_panel.cpp).
enum class EditorSection { Panel, Quality };

// Hints for the editor's drag widget (the format's range is the row's).
struct Widget {
    double speed = 0.01;
    double minimum = 0;  // reals: the drag's own limits inside the format's range
    double maximum = 0;
    const char* format = "%.3f";
    EditorSection section = EditorSection::Panel;
};

template <typename Owner>
struct Setting {
    std::string_view key;    // JSON
    std::string_view label;  // editor
    std::string_view unit;   // docs, editor and range messages ("degrees")
    SettingType type;
    SettingMember<Owner> member;
    RealRange range = RealRange::Any;
    double minimum = 0;
    double maximum = 0;
    std::span<const char* const> choices = {};
    Widget widget = {};
};

std::span<const Setting<Camera>> cameraSettings();
std::span<const Setting<RenderSettings>> renderSettings();
std::span<const Setting<Environment>> environmentSettings();  // without "ground", an object of its own
std::span<const Setting<Ground>> groundSettings();
std::span<const Setting<Light>> lightSettings();
std::span<const Setting<Material>> materialSettings();

}  // namespace sdfwb::scene
