// The ray inspector (I): one pixel's camera ray as the reference sees it exactly (its lit intervals per
// light and the integrand along it) beside the technique's value at that pixel and the technique's own view
// of the ray (its per-pixel intermediates there, the per-ray views that follow the picked pixel). It holds
// the inspected ray and draws the panel; the window decides which pixel, and hands it the run.
#pragma once

#include <optional>
#include <string>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "ray_inspection.h"
#include "techniques/reference/ray_probe.h"
#include "ui/text_renderer.h"
#include "ui/image_view.h"

namespace airlight {

class RayInspector {
public:
    // Inspects pixel `pixel` (x right, y down) of a `frame`-sized image of `scene`: the reference's probe
    // of its ray, and `technique`'s L_air there when `airlight` is given and has the frame's size.
    // Throws what reference::probePixel throws (a bad scene); the inspector is then empty.
    void inspect(const viz::scene::Scene& scene, glm::ivec2 frame, glm::ivec2 pixel, const std::string& technique,
                 const viz::Image* airlight);
    void clear();

    bool active() const { return mProbe.has_value(); }
    glm::ivec2 pixel() const { return {mProbe->x, mProbe->y}; }
    // The technique whose value was read when the pixel was inspected.
    const std::string& technique() const { return mTechnique; }

    // The technique's own readings at the pixel from a run of `technique` (inspectRun: each reading is a GL
    // readback), worked out once and kept until forgetRun(), which the window calls for every new run.
    const PixelInspection& readings(const viz::Technique& technique, const viz::FrameOutput& out, glm::ivec2 frame);
    void forgetRun() { mReadings.reset(); }

    // The panel in `area`: two lines (the reference's and the technique's values, and their relative
    // error), a third on a silhouette pixel (the technique's rasterised first surface is not the traced
    // ray's, report/first_hits.h; the sidecar's "first_hit"), the integrand plot with the lit intervals,
    // and beside it, when there is room, `seen`: the technique's readings when the run shown is the
    // inspected technique's (null otherwise).
    void draw(viz::ui::DrawList& dl, const viz::ui::Rect& area, float lineHeight, float scale,
              const PixelInspection* seen) const;

    // A cross on the inspected pixel in a screen-space view whose image is at `image` in the window.
    void mark(viz::ui::DrawList& dl, const viz::ui::Rect& image, const viz::ui::ImageViewTransform& transform,
              glm::ivec2 frame, float scale) const;

    // The screenshot sidecar's "inspector" (tests assert on it), with `seen` as in draw().
    nlohmann::json sidecar(const PixelInspection* seen) const;

private:
    std::optional<viz::reference::RayProbe> mProbe;
    std::string mTechnique;
    std::optional<glm::dvec3> mValue;  // the technique's L_air at the pixel, when the run had the frame's size
    std::optional<PixelInspection> mReadings;
};

}  // namespace airlight
