// The sweep's knobs are rows of the render settings table: each reads and
// writes the member its row names, with the row's choices and wholeness.

#include <gtest/gtest.h>

#include "scene/settings_table.h"
#include "tradeoff/knobs.h"

namespace sdfwb::tradeoff {
namespace {

TEST(Knobs, EachIsARenderSettingRowAndWritesItsMember) {
    ASSERT_FALSE(knobs().empty());
    for (const Knob& knob : knobs()) {
        SCOPED_TRACE(std::string(knob.name));
        ASSERT_NE(knob.setting, nullptr);
        EXPECT_EQ(knob.name, knob.setting->key);
        EXPECT_EQ(knob.choices.size(), knob.setting->choices.size());
        EXPECT_EQ(knob.integral, knob.setting->type != scene::SettingType::Real);
        EXPECT_EQ(findKnob(knob.name), &knob);
        scene::Scene s;
        double value = knob.choices.empty() ? knob.get(s) + (knob.integral ? 1.0 : 0.125) : 1.0;
        if (knob.get(s) == value) value = 0.0;
        knob.set(s, value);
        EXPECT_EQ(knob.get(s), value);
        EXPECT_EQ(formatKnobValue(knob, value), knob.choices.empty()
                                                    ? formatKnobValue(knob, knob.get(s))
                                                    : std::string(knob.choices[static_cast<size_t>(value)]));
    }
}

TEST(Knobs, EnumeratedKnobsParseTheirRowsChoiceNames) {
    const Knob* shadows = findKnob("shadows");
    ASSERT_NE(shadows, nullptr);
    for (size_t i = 0; i < std::size(scene::kShadowModeNames); ++i) {
        EXPECT_EQ(parseKnobValue(*shadows, scene::kShadowModeNames[i]), static_cast<double>(i));
    }
    EXPECT_THROW(parseKnobValue(*shadows, "sometimes"), std::invalid_argument);
}

}  // namespace
}  // namespace sdfwb::tradeoff
