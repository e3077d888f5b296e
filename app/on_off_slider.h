// A non-negative quantity that 0 switches off (a light's intensity, a medium coefficient) in the parameter
// panel: an "on" box and a log slider over a range declared with the quantity, never derived from its
// value (a light of intensity 0, or one from a millimetre model, once gave an empty or inverted range).
// 0 is the box unticked, never a slider position; ticking the box again brings back the value it had.
#pragma once

#include <string>

#include "ui/immediate.h"

namespace airlight {

class OnOffSlider {
public:
    // [lo, hi]: the slider's declared range; `fallback`: the value the box turns on to when there is
    // nothing to bring back.
    OnOffSlider(float lo, float hi, double fallback) : mLo(lo), mHi(hi), mFallback(fallback) {}

    // The box `onLabel` and, while it is ticked, the slider `label`; true when `value` changed. The value
    // is written only when a widget changes it, so an untouched quantity keeps its exact double, also one
    // outside the slider's range (the slider then shows its end).
    bool draw(viz::ui::Context& ui, const std::string& onLabel, const std::string& label, double& value);
    // Another quantity is shown now (another light picked, another scene loaded): nothing to bring back.
    void forget() { mOff = 0.0; }

    float lo() const { return mLo; }
    float hi() const { return mHi; }

private:
    float mLo, mHi;
    double mFallback;
    double mOff = 0.0;  // the value before the box was unticked
};

}  // namespace airlight
