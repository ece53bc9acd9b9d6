// Tooltips on node fields (issue 13): every field of every kind has its
// sentence in the kind table, and the tooltip adds the table's range, unit
// and default.

#include <gtest/gtest.h>

#include "ui/field_help.h"

namespace sdfwb::ui {
namespace {

TEST(FieldHelp, EveryFieldOfEveryKindHasASentence) {
    for (const scene::KindSpec& kind : scene::allKinds()) {
        for (const scene::FieldSpec& field : kind.fields) {
            EXPECT_FALSE(field.help.empty()) << kind.name << "." << field.name;
        }
    }
}

TEST(FieldHelp, TheTooltipAddsRangeUnitAndDefault) {
    const scene::KindSpec& sphere = scene::kindSpec(scene::NodeKind::Sphere);
    EXPECT_EQ(fieldTooltip(sphere.fields[0]), "Distance from the centre to the surface\n> 0, default 1");
    const scene::KindSpec& rotate = scene::kindSpec(scene::NodeKind::Rotate);
    EXPECT_EQ(fieldTooltip(rotate.fields[0]),
              "Turns the child about x, then y, then z\nany value, degrees, default [0, 0, 0]");
    const scene::KindSpec& sdf = scene::kindSpec(scene::NodeKind::Sdf);
    EXPECT_EQ(fieldTooltip(sdf.fields[1]), "The scene material it is drawn with; empty: the default\ndefault none");
}

}  // namespace
}  // namespace sdfwb::ui
