// The ray inspector (I): the reference's lit intervals and integrand along one pixel's ray beside the
// technique's own view of it.
#include "gui_app.h"

namespace airlight {

void GuiApp::inspectPixelUnderCursor() {
    mProbe.reset();
    mPendingInspect.reset();
    // The cursor over any screen-space view (final, L_air, a frame-sized intermediate) picks the pixel.
    if (mHoveredView < 0 || !mViews.count(mHoveredView) || mOptions.width < 1) return;
    const ViewState& hovered = mViews.at(mHoveredView);
    if (!isScreenSpace(hovered) || !hovered.image.contains(mHover)) return;
    const glm::dvec2 uv = hovered.transform.paneToUv(glm::dvec2((mHover - hovered.image.min) / hovered.image.size()));
    const int x = std::clamp(int(uv.x * double(mOptions.width)), 0, mOptions.width - 1);
    const int y = std::clamp(int(uv.y * double(mOptions.height)), 0, mOptions.height - 1);
    inspectPixel(x, y);
}

void GuiApp::inspectPixel(int x, int y) {
    mProbe.reset();
    mProbeInspection.reset();
    mScene.camera = mController.camera();
    try {
        mProbe = viz::reference::probePixel(mScene, mOptions.width, mOptions.height, x, y);
    } catch (const std::exception& e) {
        mError = e.what();
        return;
    }
    mProbeTechnique = technique().id();
    // The technique's per-ray intermediates (a walk, a voxel column, per-VPL terms) follow the pixel.
    if (pickPixel(technique(), mSettings, {x, y})) mDirty = true;
    const viz::Image& a = mOutput.airlight;
    mProbeHasValue = mHaveOutput && a.width == mOptions.width && a.height == mOptions.height;
    if (mProbeHasValue) mProbeValue = {a.at(x, y, 0), a.at(x, y, 1), a.at(x, y, 2)};
}

void GuiApp::drawInspector(DrawList& dl, const Rect& area) {
    const float line = mFont->lineHeight();
    const auto& p = *mProbe;
    const double ref = p.airlight.x + p.airlight.y + p.airlight.z;
    std::string head = "ray inspector (I): pixel (" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                       ")  d = " + format("%.3g", p.d) + "  reference L_air = " + format("%.4g", p.airlight.x) +
                       format(" %.4g", p.airlight.y) + format(" %.4g", p.airlight.z);
    std::string second = mProbeTechnique + ": ";
    if (mProbeHasValue) {
        const double v = mProbeValue.x + mProbeValue.y + mProbeValue.z;
        second += format("%.4g", mProbeValue.x) + format(" %.4g", mProbeValue.y) + format(" %.4g", mProbeValue.z) +
                  (ref > 0.0 ? "   relative error " + format("%+.2f%%", 100.0 * (v - ref) / ref) : "");
    } else {
        second += "(no value at this resolution yet)";
    }
    dl.textClipped(area.min, head, kText, area.max.x);
    dl.textClipped({area.min.x, area.min.y + line}, second, kDim, area.max.x);
    viz::plot::PlotSpec spec;
    spec.xLabel = "t along the ray";
    spec.yLabel = "integrand (sum of RGB), V included";
    viz::plot::Series curve{"integrand", viz::plot::categoricalColour(0), {}, true, false};
    for (std::size_t i = 0; i < p.t.size(); ++i) {
        const glm::dvec3& v = p.integrand[i];
        curve.points.push_back({p.t[i], v.x + v.y + v.z});
    }
    spec.series.push_back(std::move(curve));
    // The technique's own samples along the ray (slices: one point per plane), on the same axes.
    if (mHaveOutput && technique().id() == mProbeTechnique)
        for (const viz::plot::Series& s : probeInspection().series) spec.series.push_back(s);
    for (std::size_t k = 0; k < p.lights.size(); ++k) {
        viz::plot::Band band{"lit: " + p.lights[k].name, viz::plot::categoricalColour(int(k) + 1), {}};
        for (const auto& iv : p.lights[k].lit) band.spans.push_back({iv.a, iv.b});
        spec.bands.push_back(std::move(band));
    }
    Rect plotArea{{area.min.x, area.min.y + 2.0f * line + 4.0f * mScale}, area.max};
    // The technique's own view of the ray beside the plot: its per-pixel intermediates at this pixel
    // and the per-ray views that follow the picked pixel.
    if (mHaveOutput && technique().id() == mProbeTechnique && plotArea.size().x > 500.0f * mScale) {
        const Rect side{{plotArea.max.x - 0.42f * plotArea.size().x, plotArea.min.y}, plotArea.max};
        plotArea.max.x = side.min.x - kPad * mScale;
        float y = side.min.y;
        const PixelInspection& seen = probeInspection();
        const std::vector<std::string>& perRay = seen.rayViews;
        std::string title = mProbeTechnique + " at this pixel";
        if (!perRay.empty()) {
            title += " (its ray in views:";
            for (const std::string& id : perRay) title += " " + id;
            title += ")";
        }
        dl.textClipped({side.min.x, y}, title + ":", kAccent, side.max.x);
        y += line;
        for (const PixelReading& r : seen.readings) {
            if (y + line > side.max.y) break;
            std::string text = r.label + ":";
            for (int c = 0; c < std::min(r.channels, 4); ++c) text += format(" %.4g", r.value[c]);
            if (!r.units.empty()) text += " " + r.units;
            dl.textClipped({side.min.x, y}, text, kText, side.max.x);
            y += line;
        }
    }
    if (plotArea.size().y > 4.0f * line) viz::plot::drawPlot(dl, plotArea, spec);
}

void GuiApp::markProbe(DrawList& dl, const ViewState& v) {
    if (!mProbe || mOptions.width < 1 || !isScreenSpace(v)) return;
    const glm::dvec2 uv = (glm::dvec2(mProbe->x, mProbe->y) + 0.5) / glm::dvec2(mOptions.width, mOptions.height);
    const glm::vec2 c = v.image.min + glm::vec2(v.transform.uvToPane(uv)) * v.image.size();
    if (!v.image.contains(c)) return;
    const float r = 6.0f * mScale;
    dl.line({c.x - r, c.y}, {c.x + r, c.y}, 2.0f * mScale, {1.0f, 0.2f, 0.8f, 1.0f});
    dl.line({c.x, c.y - r}, {c.x, c.y + r}, 2.0f * mScale, {1.0f, 0.2f, 0.8f, 1.0f});
}

}  // namespace airlight
