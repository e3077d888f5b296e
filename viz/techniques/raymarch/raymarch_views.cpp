#include "render/intermediates.h"
#include "techniques/raymarch/raymarch_technique.h"

namespace viz::raymarch_detail {

void RaymarchTechnique::publishMarch(FrameOutput& out, const FrameInput& input) const {
    out.intermediates.push_back(render::textureIntermediate(
        kAirlight, "L_air",
        "single-scattered light reaching the eye (the quantity every technique computes)", "radiance",
        ViewKind::Colour, 0.0f, 1.0f, mAirlight));
    out.intermediates.push_back(render::textureIntermediate(
        kLitFraction, "Lit fraction", "fraction of the ray samples that the shadow maps call lit", "",
        ViewKind::Scalar, 0.0f, 1.0f, mLitFraction));
    render::readBackAirlight(input, mAirlight, out);
}

std::vector<ViewMarker> RaymarchTechnique::markersFor(glm::ivec2 pixel, const std::string& id) const {
    return mView.shadowMapMarkers(pixel, id, "raymarch");
}

}  // namespace viz::raymarch_detail
