// The ray inspector (I): the reference's lit intervals and integrand along one pixel's ray beside the
// technique's own view of it.
#include "gui_app.h"

namespace airlight {

void GuiApp::inspectPixelUnderCursor() {
    mInspector.clear();
    mPendingInspect.reset();
    // The cursor over any screen-space view (final, L_air, a frame-sized intermediate) picks the pixel.
    if (mHoveredView < 0 || !mGrid.views.count(mHoveredView) || mState.size.x < 1) return;
    const ViewState& hovered = mGrid.views.at(mHoveredView);
    if (!isScreenSpace(hovered) || !hovered.image.contains(mHover)) return;
    const glm::dvec2 uv = hovered.transform.paneToUv(glm::dvec2((mHover - hovered.image.min) / hovered.image.size()));
    const int x = std::clamp(int(uv.x * double(mState.size.x)), 0, mState.size.x - 1);
    const int y = std::clamp(int(uv.y * double(mState.size.y)), 0, mState.size.y - 1);
    inspectPixel(x, y);
}

void GuiApp::inspectPixel(int x, int y) {
    mScene.camera = mController.camera();
    try {
        mInspector.inspect(mScene, mState.size, {x, y}, technique().id(),
                           mHaveOutput ? &mOutput.airlight : nullptr);
    } catch (const std::exception& e) {
        mError = e.what();
        return;
    }
    // The technique's per-ray intermediates (a walk, a voxel column, per-VPL terms) follow the pixel.
    if (pickPixel(technique(), mState.settings, {x, y})) mDirty = true;
}

const PixelInspection* GuiApp::inspectedReadings() {
    if (!mInspector.active() || !mHaveOutput || technique().id() != mInspector.technique()) return nullptr;
    return &mInspector.readings(technique(), mOutput, mState.size);
}

}  // namespace airlight
