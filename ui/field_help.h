#pragma once
// The inspector's tooltip for a node field, from the node kind table
// (scene/node_kinds.h): the field's sentence, then its range, unit and
// default, so that nothing about a field is written twice.

#include <string>

#include "scene/node_kinds.h"

namespace sdfwb::ui {

// "Distance from the centre to the surface\n> 0, default 1".
std::string fieldTooltip(const scene::FieldSpec& field);

}  // namespace sdfwb::ui
