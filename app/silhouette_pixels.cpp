#include "silhouette_pixels.h"

#include <stdexcept>
#include <string>

#include "gl/readback.h"
#include "techniques/registry.h"

namespace airlight {

viz::Image rasterisedDistance(const viz::scene::Scene& scene, int width, int height) {
    constexpr const char* kDistance = "raymarch.distance";
    auto t = viz::makeTechnique("raymarch");
    viz::FrameInput in = viz::frameInput(&scene, width, height, viz::completeSettings(*t, {}));
    in.stopAfterStage = viz::stageOfIntermediate(t->stages(), kDistance);
    const viz::FrameOutput out = t->run(in);
    for (const viz::Intermediate& i : out.intermediates)
        if (i.id == kDistance) return i.image ? *i.image : viz::gl::readTexture(i.glTexture);
    throw std::runtime_error(std::string("raymarch published no ") + kDistance);
}

const viz::Image* tracedDistance(const viz::FrameOutput& referenceRun) {
    for (const viz::Intermediate& i : referenceRun.intermediates)
        if (i.id == "reference.distance" && i.image) return i.image.get();
    return nullptr;
}

viz::report::FirstHitMask silhouetteMask(const viz::Image& traced, const viz::scene::Scene& scene) {
    return viz::report::firstHitAgreement(traced, rasterisedDistance(scene, traced.width, traced.height));
}

}  // namespace airlight
