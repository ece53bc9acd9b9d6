#pragma once
// The range rules of the settings tables (scene/settings_table.h), as one
// reason per value. The JSON reader applies them to what it read, the model
// validator (scene/scene_validation.h) to what an edit made: one rule, two
// callers, the same words.

#include <cmath>
#include <string>

#include "scene/settings_table.h"

namespace sdfwb::scene {

// "" when `v` is a valid integer setting of `row` (read as a double, so 2.5 is caught).
template <typename Owner>
std::string integerProblem(const Setting<Owner>& row, double v) {
    if (v != std::floor(v) || v < row.minimum || v > row.maximum) {
        return "must be a whole number from " + std::to_string(static_cast<int>(row.minimum)) + " to " +
               std::to_string(static_cast<int>(row.maximum)) + " (got " + formatNumber(v) + ")";
    }
    return "";
}

template <typename Owner>
std::string realProblem(const Setting<Owner>& row, double v) {
    // the unbounded ranges word their rules as node fields do (scene/node_kinds.h)
    switch (row.range) {
    case RealRange::Any: return checkScalar(Range::Any, v);
    case RealRange::Positive: return checkScalar(Range::Positive, v);
    case RealRange::NonNegative: return checkScalar(Range::NonNegative, v);
    case RealRange::Closed:
    case RealRange::Open: break;
    }
    if (!std::isfinite(v)) return checkScalar(Range::Any, v);
    const bool inside = row.range == RealRange::Closed ? v >= row.minimum && v <= row.maximum
                                                       : v > row.minimum && v < row.maximum;
    if (inside) return "";
    const std::string unit = row.unit.empty() ? "" : " " + std::string(row.unit);
    const std::string ends = formatNumber(row.minimum) +
                             (row.range == RealRange::Closed ? " to " : " and ") + formatNumber(row.maximum);
    return (row.range == RealRange::Closed ? "must be from " : "must be strictly between ") + ends + unit + " (got " +
           formatNumber(v) + ")";
}

// Colours, vectors and directions whose components are already finite numbers.
inline std::string colourProblem(const glm::dvec3& v) {
    return v.x < 0 || v.y < 0 || v.z < 0 ? "colour components must be >= 0" : "";
}
inline std::string directionProblem(const glm::dvec3& v) {
    return v == glm::dvec3(0.0) ? "must not be the zero vector" : "";
}

struct SettingProblem {
    std::string suffix;  // appended to the setting's path: "" or "[1]"
    std::string reason;  // "" when the value is valid
};

// The rule of `row` applied to the value `owner` holds.
template <typename Owner>
SettingProblem settingProblem(const Setting<Owner>& row, const Owner& owner) {
    switch (row.type) {
    case SettingType::Integer: return {"", integerProblem(row, owner.*std::get<int Owner::*>(row.member))};
    case SettingType::Real: return {"", realProblem(row, owner.*std::get<double Owner::*>(row.member))};
    case SettingType::Colour:
    case SettingType::Vector:
    case SettingType::Direction: {
        const glm::dvec3& v = owner.*std::get<glm::dvec3 Owner::*>(row.member);
        for (int i = 0; i < 3; ++i) {
            if (!std::isfinite(v[i])) return {"[" + std::to_string(i) + "]", checkScalar(Range::Any, v[i])};
        }
        if (row.type == SettingType::Colour) return {"", colourProblem(v)};
        if (row.type == SettingType::Direction) return {"", directionProblem(v)};
        return {};
    }
    case SettingType::Choice:
    case SettingType::Flag:
    case SettingType::Text:
    case SettingType::ImageFile: return {};
    }
    return {};
}

}  // namespace sdfwb::scene
