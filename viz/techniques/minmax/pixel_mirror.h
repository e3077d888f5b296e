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
#include "techniques/minmax/epipolar.h"
#include "techniques/minmax/minmax_tree.h"

namespace viz::minmax {

struct MirrorLight {
    LightKind kind = LightKind::Spot;
    glm::vec3 position{0.0f};   // eye-relative (spot, point)
    glm::vec3 direction{0.0f};  // spot axis / directional travel direction
    glm::vec3 radiant{0.0f};    // colour * intensity
    float spotScale = 1.0f, spotOffset = 0.0f;  // KHR angular attenuation (GpuLight::spot.xy)
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

// lights.glsl lightIntensity for a spot without cookie (the mirror does not sample cookies), a point or a
// directional light.
inline glm::vec3 mirrorIntensity(const MirrorLight& L, glm::vec3 p) {
    if (L.kind != LightKind::Spot) return L.radiant;
    const glm::vec3 dir = glm::normalize(p - L.position);
    const float a = std::clamp(glm::dot(L.direction, dir) * L.spotScale + L.spotOffset, 0.0f, 1.0f);
    const float A = a * a;
    if (A == 0.0f) return glm::vec3(0.0f);
    return L.radiant * A;
}

inline float mirrorDistanceAtColumn(const EpipolarFrame<float>& f, float beta, float c, float cEnd, float d) {
    if (c >= cEnd) return d;
    return std::min(distanceAtGamma(f, beta, gammaOfColumn(f, c)), d);
}

// integrateRun of traverse.comp.
inline glm::vec3 mirrorRun(const EpipolarFrame<float>& f, const MirrorLight& L, const MirrorMedium& m, glm::vec3 w,
                           airlight::RayLightGeometry<float> g, float beta, float c0, float c1, float cEnd, float d,
                           int pieces) {
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
    const float cellColumns = float(f.columns) / float(pieces);
    glm::vec3 sum(0.0f);
    float c = c0;
    for (int cell = int(std::floor(c0 / cellColumns)) + 1; c < c1; ++cell) {
        const float next = std::min(c1, float(cell) * cellColumns);
        if (next <= c) continue;
        const float ta = mirrorDistanceAtColumn(f, beta, c, cEnd, d);
        const float tb = mirrorDistanceAtColumn(f, beta, next, cEnd, d);
        const float tm = mirrorDistanceAtColumn(f, beta, 0.5f * (c + next), cEnd, d);
        const glm::vec3 I = mirrorIntensity(L, tm * w);
        if (tb > ta && I != glm::vec3(0.0f))
            sum += airlight::pointSegment<float>(g.tP, g.h, ta, tb, m.sigmaS, m.sigmaT, m.g, 1.0f) * I;
        c = next;
    }
    return sum;
}

// One pixel: w its ray, (beta, cEnd, d) from minmax.ray_coords, `tree` the 2n nodes of its slice's row.
// A point light's f is its row's frame (EpipolarFrame::withGammaRange with minmax.row_gamma).
inline MirrorResult integratePixel(const EpipolarFrame<float>& f, const MirrorLight& L, const MirrorMedium& m,
                                   glm::vec3 w, float beta, float cEnd, float d,
                                   const std::vector<glm::vec2>& tree, int pieces) {
    MirrorResult r;
    const float end = std::min(cEnd, float(f.columns));
    const auto g = airlight::rayLightGeometry<float>(L.position, w);
    if (end > 0.0f) {
        r.visited = traverse(
            tree, beta, end,
            [&](const LitRun& run) {
                r.runs.push_back(run);
                r.airlight += mirrorRun(f, L, m, w, g, beta, run.begin, run.end, cEnd, d, pieces);
            },
            [&](const VisitedNode& v) { r.nodes.push_back(v); });
    }
    if (f.kind == LightKind::Directional && cEnd > float(f.columns)) {
        r.runs.push_back({float(f.columns), cEnd});
        r.airlight += mirrorRun(f, L, m, w, g, beta, float(f.columns), cEnd, cEnd, d, pieces);
    }
    return r;
}

}  // namespace viz::minmax
