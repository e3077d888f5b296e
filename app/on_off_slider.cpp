#include "on_off_slider.h"

namespace airlight {

bool OnOffSlider::draw(viz::ui::Context& ui, const std::string& onLabel, const std::string& label, double& value) {
    bool changed = false;
    bool on = value > 0.0;
    if (ui.checkbox(onLabel, on)) {
        if (on) {
            value = mOff > 0.0 ? mOff : mFallback;
        } else {
            mOff = value;
            value = 0.0;
        }
        changed = true;
    }
    if (on) {
        float shown = float(value);
        if (ui.sliderFloat(label, shown, mLo, mHi, true)) {
            value = shown;
            changed = true;
        }
    }
    return changed;
}

}  // namespace airlight
