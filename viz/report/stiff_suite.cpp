#include "report/stiff_suite.h"

#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "core/text.h"
#include "scene/camera.h"

namespace viz::report {

namespace {

using viz::format;

}  // namespace

Image stiffExclusionMask(const scene::StiffCase& c, const scene::Scene& scene) {
    Image mask(c.width, c.height, 1);
    if (c.excludeAroundLight <= 0.0) return mask;
    const scene::Camera& cam = scene.camera;
    const double tanHalf = std::tan(cam.yfov * 0.5), aspect = scene::aspectOf(cam, c.width, c.height);
    for (const scene::Light& l : scene.lights) {
        if (l.type != scene::LightType::Point && l.type != scene::LightType::Spot) continue;
        const glm::dvec3 d = l.position - cam.position;
        const double z = glm::dot(d, cam.forward);
        if (z <= 0.0) continue;
        // Inverse of scene::pixelRay: pixel coordinates of the light's projection.
        const double px = (glm::dot(d, scene::cameraRight(cam)) / (z * tanHalf * aspect) + 1.0) * 0.5 * c.width - 0.5;
        const double py = (1.0 - glm::dot(d, cam.up) / (z * tanHalf)) * 0.5 * c.height - 0.5;
        for (int y = 0; y < c.height; ++y)
            for (int x = 0; x < c.width; ++x)
                if (std::hypot(x - px, y - py) <= c.excludeAroundLight) mask.at(x, y) = 1.0f;
    }
    return mask;
}

StiffOutcome runStiffCase(Technique& technique, const scene::StiffCase& c, const scene::Scene& scene, const Image& reference) {
    StiffOutcome o;
    o.caseId = c.id;
    o.caseClass = c.caseClass;
    o.technique = technique.id();
    o.bound = technique.stiffBound(c.caseClass);
    FrameOutput out;
    try {
        FrameInput in;
        in.scene = &scene;
        in.width = c.width;
        in.height = c.height;
        setRunSettings(in, completeSettings(technique, technique.stiffSettings()));
        out = technique.run(in);
    } catch (const InputError& e) {
        o.refusal = e.what();
        o.passed = !o.bound.has_value();
        o.verdict = o.passed ? "refused, as it declares for this class: " + o.refusal
                             : "refused although it declares a bound for this class: " + o.refusal;
        return o;
    }
    o.ran = true;
    o.milliseconds = out.timing.totalMilliseconds();
    if (out.airlight.empty() || out.airlight.width != reference.width || out.airlight.height != reference.height) {
        o.verdict = "produced no L_air image of the case's size";
        return o;
    }
    // Finite checks see every pixel; the error figures leave the excluded ones out (zeroed in both).
    countNonFinite(out.airlight, o.error);
    const ErrorMetrics counts = o.error;
    Image test = out.airlight, ref = reference;
    const Image mask = stiffExclusionMask(c, scene);
    for (int y = 0; y < test.height; ++y)
        for (int x = 0; x < test.width; ++x)
            if (mask.at(x, y) != 0.0f)
                for (int ch = 0; ch < test.channels; ++ch) test.at(x, y, ch) = ref.at(x, y, ch) = 0.0f;
    o.error = compareImages(test, ref);
    o.error.nanPixels = counts.nanPixels, o.error.infPixels = counts.infPixels;
    o.error.negativePixels = counts.negativePixels;

    if (o.error.nanPixels || o.error.infPixels || o.error.negativePixels) {
        o.verdict = std::to_string(o.error.nanPixels) + " NaN, " + std::to_string(o.error.infPixels) + " Inf, " +
                    std::to_string(o.error.negativePixels) + " negative pixels";
        return o;
    }
    if (!o.bound) {
        o.verdict = "ran, but declares no bound for class '" + c.caseClass + "' (it should refuse or declare one)";
        return o;
    }
    double refMax = 0.0;
    for (float v : ref.pixels) refMax = std::max(refMax, double(v));
    if (refMax == 0.0) {
        // Nothing is lit along any ray: the only right answer is zero.
        o.passed = o.error.maxAbsolute == 0.0;
        o.verdict = o.passed ? "reference and result are zero everywhere"
                             : "the reference is zero everywhere but the result is not (max " +
                                   format("%.3g", o.error.maxAbsolute) + ")";
        return o;
    }
    o.passed = o.error.relativeL2 <= o.bound->relativeL2;
    o.verdict = "relative L2 " + format("%.3g", o.error.relativeL2) + (o.passed ? " <= " : " > ") + "bound " +
                format("%.3g", o.bound->relativeL2);
    return o;
}

}  // namespace viz::report
