// The parameter panel's widgets (app/parameter_widgets.h) driven by synthetic input, no window: every
// declared parameter of every registered technique, dragged or clicked from one end of its widget to the
// other, only ever takes values inside its declared range (whole for integers, a valid index for
// choices), starting from its default, its ends and a value outside the range. The preset picker sets
// exactly the paper's values, and the defaults back.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "parameter_widgets.h"
#include "techniques/registry.h"
#include "cpu/ui/synthetic_panel.h"

namespace airlight {
namespace {

using viz::ui::Context;
using viz::ui::Input;

using Panel = viz::ui::testing::SyntheticPanel;

// Every value the widget hands back while the mouse presses at `from`, moves to `to` in steps and lets go.
void gesture(Panel& panel, const viz::ParamInfo& p, double& value, glm::vec2 from, glm::vec2 to,
             const std::function<void(double)>& check) {
    const auto ui = [&](Context& c) {
        if (parameterWidget(c, p, value)) check(value);
    };
    panel.frame(Panel::at(from, false), ui);
    panel.frame(Panel::at(from, true), ui);
    for (int k = 1; k <= 8; ++k) panel.frame(Panel::at(from + (to - from) * (float(k) / 8.0f), true), ui);
    panel.frame(Panel::at(to, false), ui);
    // A popup (a combo's list) may be open now: a click lower down picks an item.
    panel.frame(Panel::at({from.x, from.y + 40.0f}, true), ui);
    panel.frame(Panel::at({from.x, from.y + 40.0f}, false), ui);
}

TEST(ParameterWidgets, EveryDeclaredParameterStaysInsideItsDeclaredRange) {
    int parameters = 0, changes = 0;
    for (const std::string& id : viz::techniqueIds()) {
        const auto technique = viz::makeTechnique(id);
        for (const viz::ParamInfo& p : technique->params()) {
            SCOPED_TRACE(id + "." + p.name);
            ++parameters;
            const ParamWidget kind = paramWidgetFor(p);
            if (kind != ParamWidget::Choice) {
                ASSERT_LT(p.minValue, p.maxValue) << "an empty or inverted range";
            }
            if (kind == ParamWidget::LogSlider) {
                ASSERT_GT(p.minValue, 0.0) << "a log slider needs a positive range";
            }
            const auto check = [&](double v) {
                ++changes;
                ASSERT_TRUE(std::isfinite(v));
                if (kind == ParamWidget::Choice) {
                    EXPECT_GE(v, 0.0);
                    EXPECT_LT(v, double(p.choices.size()));
                } else {
                    EXPECT_GE(v, p.minValue);
                    EXPECT_LE(v, p.maxValue);
                }
                if (p.integer || kind == ParamWidget::Choice) {
                    EXPECT_EQ(v, std::round(v));
                }
            };
            const double far = p.maxValue + std::max(1.0, std::abs(p.maxValue));
            for (double start : {p.defaultValue, p.minValue, p.maxValue, far}) {
                Panel panel;
                double value = start;
                panel.frame({}, [&](Context& c) { parameterWidget(c, p, value); });
                const auto it = panel.ctx.widgetRects().find(p.name);
                ASSERT_NE(it, panel.ctx.widgetRects().end());
                const viz::ui::Rect r = it->second;
                const float y = (r.min.y + r.max.y) * 0.5f;
                // Across the widget both ways, and on past its ends.
                gesture(panel, p, value, {r.min.x + 2.0f, y}, {r.max.x + 300.0f, y}, check);
                gesture(panel, p, value, {r.max.x - 2.0f, y}, {r.min.x - 300.0f, y}, check);
            }
        }
    }
    EXPECT_GT(parameters, 50);
    EXPECT_GT(changes, parameters) << "the gestures should move most widgets";
}

TEST(ParameterWidgets, ThePresetPickerSetsThePapersValuesAndTheDefaultsBack) {
    int withPaper = 0;
    for (const std::string& id : viz::techniqueIds()) {
        const auto technique = viz::makeTechnique(id);
        const viz::Settings paper = technique->paperSettings();
        const viz::Settings defaults = viz::completeSettings(*technique, {});
        Panel panel;
        std::optional<viz::Settings> picked;
        viz::Settings current = defaults;
        const auto ui = [&](Context& c) {
            if (auto p = presetWidget(c, *technique, current)) picked = p;
        };
        panel.frame({}, ui);
        const auto it = panel.ctx.widgetRects().find("preset");
        if (paper.empty()) {
            EXPECT_EQ(it, panel.ctx.widgetRects().end()) << id << ": no paper configuration, no picker";
            continue;
        }
        ++withPaper;
        ASSERT_NE(it, panel.ctx.widgetRects().end()) << id;
        // A copy: the next frame rebuilds the widgets' rectangles (and frees the one `it` points at).
        const viz::ui::Rect box = it->second;
        const glm::vec2 c = (box.min + box.max) * 0.5f;
        // Open the list and pick its second item ("paper"), a row below the first.
        const float row = box.size().y;
        for (auto [p, down] : std::vector<std::pair<glm::vec2, bool>>{
                 {c, true}, {c, false}, {{c.x, box.max.y + 1.5f * row}, true}, {{c.x, box.max.y + 1.5f * row}, false}})
            panel.frame(Panel::at(p, down), ui);
        ASSERT_TRUE(picked) << id;
        EXPECT_EQ(*picked, paper) << id;
        for (const auto& [name, value] : *picked) current[name] = value;
        picked.reset();
        // From the paper's values, the first item ("ours") brings the defaults back.
        panel.frame({}, ui);
        for (auto [p, down] : std::vector<std::pair<glm::vec2, bool>>{
                 {c, true}, {c, false}, {{c.x, box.max.y + 0.5f * row}, true}, {{c.x, box.max.y + 0.5f * row}, false}})
            panel.frame(Panel::at(p, down), ui);
        ASSERT_TRUE(picked) << id;
        for (const auto& [name, value] : *picked) EXPECT_EQ(value, defaults.at(name)) << id << "." << name;
        EXPECT_EQ(picked->size(), paper.size());
    }
    EXPECT_GE(withPaper, 3);
}

}  // namespace
}  // namespace airlight
