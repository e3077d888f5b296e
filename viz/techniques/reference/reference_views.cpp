#include <algorithm>
#include <memory>

#include "techniques/reference/reference_technique.h"

namespace viz::reference_detail {

void ReferenceTechnique::publish(FrameOutput& out, const FrameState& f, const scene::Scene& scene, int stopAfter) const {
    auto add = [&](const char* id, const char* label, const char* note, const char* units, ViewKind kind,
                   const Image& img, float lo, float hi) {
        out.intermediates.push_back(cpuIntermediate(id, label, note, kind, std::make_shared<const Image>(img), lo, hi));
        out.intermediates.back().units = units;
    };
    auto maxOf = [](const Image& img) {
        float m = 0.0f;
        for (float v : img.pixels) m = std::max(m, v);
        return m > 0.0f ? m : 1.0f;
    };
    if (stopAfter >= kTrace)
        add(kDistance, "Distance d", "distance along the pixel ray to the first surface, zfar for sky",
            "scene units", ViewKind::Depth, f.distanceImage, 0.0f, float(scene.camera.zfar));
    if (stopAfter >= kVisibility) {
        add(kTransitions, "Shadow transitions", "lit/unlit changes along [0, d], summed over lights and area cells",
            "count", ViewKind::Scalar, f.transitions, 0.0f, maxOf(f.transitions));
        add(kLitFraction, "Lit fraction", "lit length / d, averaged over lights", "fraction", ViewKind::Scalar,
            f.litFraction, 0.0f, 1.0f);
    }
    if (stopAfter >= kAirlightStage) {
        // Radiance as the GPU techniques publish it: [0, 1] at the window's exposure, so the same
        // quantity looks the same in every technique; the caption is theirs too.
        add(kAirlight, "L_air", "single scattering along [0, d], every light", "radiance", ViewKind::Colour,
            f.airlight, 0.0f, 1.0f);
        out.airlight = f.airlight;
    }
    if (stopAfter >= kSurfaceStage)
        add(kSurface, "Surface radiance", "Lambert + emitted, before attenuation by exp(-sigma_t d)", "radiance",
            ViewKind::Colour, f.surface, 0.0f, 1.0f);
    if (stopAfter >= kFinalStage) {
        add(kFinal, "Final", "surface * exp(-sigma_t d) + L_air", "radiance", ViewKind::Colour, f.final, 0.0f,
            1.0f);
        out.final = f.final;
    }
    out.lastStageRun = stopAfter;
}

bool ReferenceTechnique::fromCache(const reference::CachedImages& c, const scene::Scene& scene, const FrameInput& input,
               FrameOutput& out) const {
    FrameState f;
    const struct {
        const char* id;
        Image* image;
        int channels;
    } wanted[] = {{kDistance, &f.distanceImage, 1}, {kTransitions, &f.transitions, 1},
                  {kLitFraction, &f.litFraction, 1}, {kAirlight, &f.airlight, 3},
                  {kSurface, &f.surface, 3},         {kFinal, &f.final, 3}};
    for (const auto& wnt : wanted) {
        const Image* img = c.find(wnt.id);
        if (!img || img->channels != wnt.channels || img->width != input.width || img->height != input.height)
            return false;
        *wnt.image = *img;
    }
    out.plan = plan(scene, input.settings);
    publish(out, f, scene, int(mStages.size()) - 1);
    return true;
}

}  // namespace viz::reference_detail
