#include "ui/field_help.h"

#include <sstream>

namespace sdfwb::ui {
namespace {

std::string rangeText(scene::Range range) {
    using enum scene::Range;
    switch (range) {
    case Any: return "any value";
    case Positive: return "> 0";
    case NonNegative: return ">= 0";
    case Integer2or3: return "2 or 3";
    case NonNegativeInteger: return "whole numbers >= 0";
    case OpenAngle90: return "between 0 and 90 degrees, exclusive";
    case NonZeroVector: return "not zero";
    case SdfFormula: return "a signed distance formula";
    case ImplicitFormula: return "an implicit formula";
    case PolynomialFormula: return "a polynomial formula";
    }
    return "";
}

std::string valueText(const scene::FieldValue& value) {
    std::ostringstream out;
    if (const double* v = std::get_if<double>(&value)) {
        out << *v;
    } else if (const glm::dvec3* v = std::get_if<glm::dvec3>(&value)) {
        out << "[" << v->x << ", " << v->y << ", " << v->z << "]";
    } else {
        const std::string& text = std::get<std::string>(value);
        out << (text.empty() ? "none" : text);
    }
    return out.str();
}

}  // namespace

std::string fieldTooltip(const scene::FieldSpec& field) {
    std::string text(field.help);
    text += "\n";
    using enum scene::FieldType;
    if (field.type == Real || field.type == Vec3) text += rangeText(field.range) + ", ";
    if (!field.unit.empty()) text += std::string(field.unit) + ", ";
    if (field.type != Formula)
        text += "default " + valueText(field.defaultValue);
    else
        text += rangeText(field.range);
    return text;
}

}  // namespace sdfwb::ui
