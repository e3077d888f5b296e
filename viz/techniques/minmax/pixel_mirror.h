// CPU mirror of one pixel of shaders/minmax/traverse.comp (`integrand=analytic`, tree traversal): the
// same steps in float, node by node, so the debugger can show a picked pixel's walk (Figure 4 of Chen et
// al. 2011) and tests can compare it with the GPU. It starts from the values the GPU stored for the
// pixel (slice row, beta, end column cEnd, distance d: minmax.ray_coords) and the row of the tree the GPU
// built, so the node sequence is the GPU's exactly; the integral differs only by the last bits of the
// transcendental functions (GLSL's atan/sin/exp/log are not the C library's).
#pragma once

#include <cmath>
#include <vector>

#include <glm/glm.hpp>

#include "shared/airlight.h"
#include "shared/spot_cone.h"
#include "techniques/minmax/epipolar.h"
#include "techniques/minmax/minmax_tree.h"

namespace viz::minmax {

struct MirrorLight {
    LightKind kind = LightKind::Spot;
    glm::vec3 position{0.0f};   // eye-relative (spot, point)
    glm::vec3 direction{0.0f};  // spot axis / directional travel direction
    glm::vec3 radiant{0.0f};    // colour * intensity
    float spotScale = 1.0f, spotOffset = 0.0f;  // KHR angular attenuation (GpuLight::spot.xy)
    float spotCosOuter = 0.0f;                  // cos(outer) (GpuLight::spot.w)
};

struct MirrorMedium {
    float sigmaS = 0.0f, sigmaT = 0.0f, g = 0.0f;
};

struct MirrorResult {
    glm::vec3 airlight{0.0f};
    std::vector<VisitedNode> nodes;  // in visiting order
    std::vector<LitRun> runs;        // lit runs, in columns
    int visited = 0;
};

inline float mirrorDistanceAtColumn(const EpipolarFrame<float>& f, float beta, float c, float cEnd, float d) {
    if (c >= cEnd) return d;
    return std::min(distanceAtGamma(f, beta, gammaOfColumn(f, c)), d);
}

// integrateRun of traverse.comp.
inline glm::vec3 mirrorRun(const EpipolarFrame<float>& f, const MirrorLight& L, const MirrorMedium& m, glm::vec3 w,
                           airlight::RayLightGeometry<float> g, float beta, float c0, float c1, float cEnd, float d) {
    if (f.kind == LightKind::Directional) {
        const float t0 = mirrorDistanceAtColumn(f, beta, c0, cEnd, d);
        const float t1 = mirrorDistanceAtColumn(f, beta, c1, cEnd, d);
        return airlight::directionalSegment(std::cos(beta), t0, t1, m.sigmaS, m.sigmaT, m.g, 1.0f) * L.radiant;
    }
    if (f.kind == LightKind::Point) {
        const float t0 = mirrorDistanceAtColumn(f, beta, c0, cEnd, d);
        const float t1 = mirrorDistanceAtColumn(f, beta, c1, cEnd, d);
        if (t1 <= t0) return glm::vec3(0.0f);
        return airlight::pointSegment<float>(g.tP, g.h, t0, t1, m.sigmaS, m.sigmaT, m.g, 1.0f) * L.radiant;
    }
    // A spot (the mirror samples no cookie): the run cut at the cones, each part one segment integral.
    const float t0 = mirrorDistanceAtColumn(f, beta, c0, cEnd, d);
    const float t1 = mirrorDistanceAtColumn(f, beta, c1, cEnd, d);
    if (!(t1 > t0)) return glm::vec3(0.0f);
    const float cosInner = std::min((1.0f - L.spotOffset) / L.spotScale, 1.0f);
    const airlight::SpotCuts<float> cuts =
        airlight::spotConeCuts(L.position, L.direction, L.spotCosOuter, cosInner, w, g, t0, t1);
    float sum = 0.0f;
    for (int i = 0; i < cuts.n; ++i) {
        const float ta = cuts.breaks[i], tb = i + 1 < cuts.n ? cuts.breaks[i + 1] : t1;
        if (!(tb > ta)) continue;
        const airlight::SpotZone zone = airlight::spotZone(L.direction, L.spotCosOuter, cosInner, cuts, w, g.tP, ta, tb);
        if (zone == airlight::SpotZone::Inside)
            sum += airlight::pointSegment<float>(g.tP, g.h, ta, tb, m.sigmaS, m.sigmaT, m.g, 1.0f);
        else if (zone == airlight::SpotZone::Penumbra)
            sum += airlight::spotPenumbraSegment<float>(L.position, w, L.direction, L.spotScale, L.spotOffset, ta, tb,
                                                        m.sigmaS, m.sigmaT, m.g, 1.0f);
    }
    return sum * L.radiant;
}

// One pixel: w its ray, (beta, cEnd, d) from minmax.ray_coords, `tree` the 2n nodes of its slice's row.
// A point light's f is its row's frame (EpipolarFrame::withGammaRange with minmax.row_gamma).
inline MirrorResult integratePixel(const EpipolarFrame<float>& f, const MirrorLight& L, const MirrorMedium& m,
                                   glm::vec3 w, float beta, float cEnd, float d,
                                   const std::vector<glm::vec2>& tree) {
    MirrorResult r;
    const float end = std::min(cEnd, float(f.columns));
    const auto g = airlight::rayLightGeometry<float>(L.position, w);
    if (end > 0.0f) {
        r.visited = traverse(
            tree, beta, end,
            [&](const LitRun& run) {
                r.runs.push_back(run);
                r.airlight += mirrorRun(f, L, m, w, g, beta, run.begin, run.end, cEnd, d);
            },
            [&](const VisitedNode& v) { r.nodes.push_back(v); });
    }
    if (f.kind == LightKind::Directional && cEnd > float(f.columns)) {
        r.runs.push_back({float(f.columns), cEnd});
        r.airlight += mirrorRun(f, L, m, w, g, beta, float(f.columns), cEnd, cEnd, d);
    }
    return r;
}

}  // namespace viz::minmax
