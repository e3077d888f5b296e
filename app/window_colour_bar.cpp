// The colour bar under each image view: its text and frames (colour_bar_draw.h), its ramp and legend
// swatches drawn as tiny images through the view's own shader.
#include "gui_app.h"

#include "colour_bar_draw.h"
#include "colour_bar_images.h"

namespace airlight {

float GuiApp::colourBarHeight(const ViewState& v) const {
    if (!v.pane.plots.empty() || v.pane.texture == 0 || !mHaveOutput) return 0.0f;
    return airlight::colourBarHeight(*mFont, mScale);
}

void GuiApp::drawColourBar(int id, ViewState& v) {
    v.colourBar = {};
    if (v.bar.size().y <= 0.0f) return;
    const DisplayMapping mapping = resolveMapping(v.pane, v.display, mState.exposure, v.measured);
    v.colourBar = colourBarFor(v.pane, mapping, v.counts);
    // A mask's count, once per values and mapping (a large image costs milliseconds to count).
    const auto& memo = v.maskMemo;
    if (mapping.mode == DisplayMode::Mask &&
        !(memo && memo->lo == mapping.lo && memo->hi == mapping.hi && memo->channel == mapping.channel &&
          memo->log == mapping.logScale))
        if (const auto pixels = countMaskPixels(mapping, v.values, v.meaningful, v.pane.sentinels))
            v.maskMemo = ViewState::MaskMemo{mapping.lo, mapping.hi, mapping.channel, mapping.logScale, *pixels};
    if (mapping.mode == DisplayMode::Mask && v.maskMemo) describeMaskPixels(v.colourBar, v.maskMemo->pixels);
    if (v.colourBar.kind == ColourBar::Kind::None) return;
    const ColourBarLayout layout =
        drawColourBarText(v.colourBar, v.bar, *mFont, mScale, *mDrawList, *mBackground, {kText, kDim, kError, kDim});
    v.ramp = layout.ramp;
    for (const BarImageDraw& d : barImageDraws(v, layout, mapping)) mCanvas.panes.push_back({d.rect, d.pane, d.view, d.mapping});
    mCanvas.screen.place("colour_bar:" + std::to_string(id), v.bar);
    if (v.bar.contains(mHover)) mUi->tooltipNow({layout.heading, layout.legend});
}

}  // namespace airlight
