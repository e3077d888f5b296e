// The light gizmo over the frame views: where its handles are and how a drag moves the light.
#include "gui_app.h"

namespace airlight {

std::optional<LightGizmo> GuiApp::gizmoFor(const ViewState& v) const {
    if (!mShowGizmo || !mHaveOutput || mScene.lights.empty() || !LightGizmo::hasHandles(selectedLight())) return {};
    if ((v.content != "final" && v.content != "airlight") || !isScreenSpace(v)) return {};
    // It would cover what the view is showing: the inspected pixel (the ray inspector's cross), or in a
    // lesson the NaN / Inf pixels the step is about.
    if (mInspector.active() || (mLesson && v.counts.nan + v.counts.inf > 0)) return {};
    return LightGizmo(mController.camera(), v.pane.size, mGizmoArm, mController.target());
}

glm::vec2 GuiApp::frameToWindow(const ViewState& v, glm::dvec2 px) {
    return v.image.min + glm::vec2(v.transform.uvToPane(px / glm::dvec2(v.pane.size))) * v.image.size();
}

glm::dvec2 GuiApp::windowToFrame(const ViewState& v, glm::vec2 p) {
    return v.transform.paneToUv(glm::dvec2((p - v.image.min) / v.image.size())) * glm::dvec2(v.pane.size);
}

glm::vec2 GuiApp::handlePoint(const ViewState& v, glm::dvec2 px, bool& inside) const {
    const glm::vec2 p = frameToWindow(v, px);
    const float inset = 7.0f * mScale;
    const glm::vec2 q = glm::clamp(p, v.image.min + inset, v.image.max - inset);
    inside = q == p;
    return q;
}

std::optional<GizmoDrag> GuiApp::gizmoHandleAt(glm::vec2 p) const {
    const float grab = 8.0f * mScale;
    for (const ViewCellRect& c : mCells) {
        const ViewState& v = mGrid.views.at(c.view);
        const auto gizmo = gizmoFor(v);
        if (!gizmo || !v.image.contains(p)) continue;
        const GizmoHandles h = gizmo->handles(selectedLight());
        bool inside = true;
        const glm::dvec2 cursor = windowToFrame(v, p), size(v.pane.size);
        if (h.tip && glm::length(handlePoint(v, *h.tip, inside) - p) <= grab)
            return GizmoDrag{c.view, true, (*h.tip - cursor) / size};
        if (h.position && glm::length(handlePoint(v, *h.position, inside) - p) <= grab)
            return GizmoDrag{c.view, false, (*h.position - cursor) / size};
    }
    return std::nullopt;
}

void GuiApp::dragGizmo(glm::vec2 p) {
    if (!mGrid.views.count(mGizmoDrag->view) || mScene.lights.empty()) return;
    const ViewState& v = mGrid.views.at(mGizmoDrag->view);
    const auto gizmo = gizmoFor(v);
    if (!gizmo) return;
    viz::scene::Light& light = selectedLight();
    const glm::dvec2 px = windowToFrame(v, p) + mGizmoDrag->offset * glm::dvec2(v.pane.size);
    if (mGizmoDrag->direction ? gizmo->dragDirection(light, px) : gizmo->dragPosition(light, px)) sceneEdited();
}

void GuiApp::drawGizmo(DrawList& dl, int id, const ViewState& v) {
    const auto gizmo = gizmoFor(v);
    if (!gizmo) return;
    const GizmoHandles h = gizmo->handles(selectedLight());
    const float r = 5.0f * mScale, w = 1.5f * mScale;
    const glm::vec4 shadow{0.0f, 0.0f, 0.0f, 0.8f}, yellow{1.0f, 0.9f, 0.25f, 1.0f};
    dl.pushClip(v.image);
    const auto lit = [&](bool direction) {
        return (mGizmoDrag && mGizmoDrag->view == id && mGizmoDrag->direction == direction) ? kText : yellow;
    };
    bool inside = true;
    if (h.tip) {
        // The arm, when its root is in front of the camera too (a light behind the camera can still be
        // turned by its tip).
        if (h.root) {
            const glm::vec2 a = frameToWindow(v, *h.root), tip = frameToWindow(v, *h.tip);
            dl.line(a, tip, w + 2.0f * mScale, shadow);
            dl.line(a, tip, w, yellow);
        }
        const glm::vec2 b = handlePoint(v, *h.tip, inside);
        const glm::vec2 corners[4] = {{b.x, b.y - r - 1.0f}, {b.x + r + 1.0f, b.y}, {b.x, b.y + r + 1.0f}, {b.x - r - 1.0f, b.y}};
        for (int pass = 0; pass < 2; ++pass)
            for (int i = 0; i < 4; ++i)
                dl.line(corners[i], corners[(i + 1) % 4], pass == 0 ? w + 2.0f * mScale : w, pass == 0 ? shadow : lit(true));
        mCanvas.screen.place("gizmo:direction", {b - r, b + r}, true);
    }
    if (h.position) {
        const glm::vec2 c = handlePoint(v, *h.position, inside);
        dl.rect({c - r - 1.0f * mScale, c + r + 1.0f * mScale}, shadow);
        // Off the view: a hollow square at the edge nearest the light.
        dl.rect({c - r, c + r}, lit(false));
        if (!inside) dl.rect({c - r + 2.0f * mScale, c + r - 2.0f * mScale}, shadow);
        const std::string name = (selectedLight().name.empty() ? std::string("light") : selectedLight().name) +
                                 (inside ? "" : " (off view)");
        const float tx = c.x + r + 4.0f * mScale + mFont->measure(name) < v.image.max.x
                             ? c.x + r + 4.0f * mScale
                             : c.x - r - 4.0f * mScale - mFont->measure(name);
        dl.textClipped({tx, c.y - 0.5f * mFont->lineHeight()}, name, yellow, v.image.max.x);
        mCanvas.screen.place("gizmo:position", {c - r, c + r}, true);
    }
    dl.popClip();
}

}  // namespace airlight
