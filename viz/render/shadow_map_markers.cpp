#include "render/shadow_map_markers.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"

namespace viz::render {

namespace {

bool isCube(const GpuLightCpu& light) { return light.info.x == hd::kLightPoint || light.info.x == hd::kLightVpl; }

// clip(t) = c0 + t c1 for the ray p(t) = t w (the eye is the origin).
struct ClipLine {
    glm::dvec4 c0{0.0}, c1{0.0};
    glm::dvec4 at(double t) const { return c0 + t * c1; }
};

ClipLine clipLine(const glm::dmat4& m, const glm::dvec3& w) { return {m[3], m * glm::dvec4(w, 0.0)}; }

// Liang-Barsky in homogeneous clip space: the part of [lo, hi] where -w <= x, y, z <= w (and w > 0).
bool clipToFrustum(const ClipLine& c, double& lo, double& hi) {
    auto keep = [&](double f0, double f1) {  // f0 + t f1 >= 0
        if (f1 == 0.0) return f0 >= 0.0;
        const double r = -f0 / f1;
        if (f1 > 0.0) lo = std::max(lo, r);
        else hi = std::min(hi, r);
        return lo < hi;
    };
    for (int axis = 0; axis < 3; ++axis) {
        if (!keep(c.c0.w + c.c0[axis], c.c1.w + c.c1[axis])) return false;
        if (!keep(c.c0.w - c.c0[axis], c.c1.w - c.c1[axis])) return false;
    }
    return lo < hi;
}

// Parameters in (lo, hi) where ndc component `axis` of the line crosses a texel boundary of an n-texel map
// (ndc = -1 + 2 k / n). ndc(t) = x(t) / w(t) is monotone wherever w > 0, so the boundaries between its
// values at the ends are all crossed, once each.
void texelCuts(const ClipLine& c, int axis, int n, double lo, double hi, std::vector<double>& cuts) {
    const auto texelCoord = [&](double t) {
        const glm::dvec4 q = c.at(t);
        return (q[axis] / q.w * 0.5 + 0.5) * double(n);
    };
    const double a = texelCoord(lo), b = texelCoord(hi);
    const int first = int(std::floor(std::min(a, b))) + 1;
    const int last = int(std::ceil(std::max(a, b))) - 1;
    for (int k = std::max(first, 1); k <= std::min(last, n - 1); ++k) {
        const double x = 2.0 * double(k) / double(n) - 1.0;
        const double denom = c.c1[axis] - x * c.c1.w;
        if (denom == 0.0) continue;
        const double t = (x * c.c0.w - c.c0[axis]) / denom;
        if (t > lo && t < hi) cuts.push_back(t);
    }
}

// Where in [ta, tb] the ray is lit by a texel storing `stored` (shadow_map.glsl's test, solved for t).
// Returns false when nowhere; otherwise [litA, litB].
bool litPart(const GpuLightCpu& light, const glm::dvec3& w, int n, double stored, double ta, double tb, double& litA,
             double& litB) {
    const double slope = double(light.shadow.z), constant = double(light.shadow.w);
    litA = ta, litB = tb;
    if (light.info.x == hd::kLightDirectional) {
        // dot(p, dir) <= stored + constant + slope / n, p = t w.
        const double rate = glm::dot(w, glm::dvec3(light.direction));
        const double limit = double(stored) + constant + slope / double(n);
        if (rate == 0.0) return 0.0 <= limit;
        const double root = limit / rate;
        if (rate > 0.0) litB = std::min(tb, root);
        else litA = std::max(ta, root);
        return litA < litB;
    }
    // Distance maps: d <= stored + constant + slope d / n, d = |p - P|, i.e. d <= R.
    const double keep = 1.0 - slope / double(n);
    if (keep <= 0.0) return true;
    const double radius = (double(stored) + constant) / keep;
    const glm::dvec3 toLight(light.position);
    const double tP = glm::dot(w, toLight);
    // The light's squared distance to the line from the perpendicular itself (no |P|^2 - tP^2 cancellation).
    const glm::dvec3 offset = toLight - tP * w;
    const double disc = radius * radius - glm::dot(offset, offset);
    if (disc < 0.0) return false;
    const double half = std::sqrt(disc);
    litA = std::max(ta, tP - half);
    litB = std::min(tb, tP + half);
    return litA < litB;
}

// "eye ray t=a..b" and "enters shadow t=3.21": distances along the ray in scene units, two decimals.
std::string stretchLabel(double a, double b, bool startsInShadow) {
    char buffer[96];
    std::snprintf(buffer, sizeof buffer, "eye ray t=%.2f..%.2f%s", a, b, startsInShadow ? " (starts in shadow)" : "");
    return buffer;
}
std::string transitionLabel(bool entersShadow, double t) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%s shadow t=%.2f", entersShadow ? "enters" : "leaves", t);
    return buffer;
}

}  // namespace

glm::dmat4 shadowMapMatrix(const GpuLightCpu& light, int face) {
    if (!isCube(light)) return glm::dmat4(light.shadowMatrix);
    // As ShadowMaps::build: a 90-degree square frustum per face, in double.
    glm::dvec3 forward, up;
    ShadowMaps::cubeFaceBasis(face, forward, up);
    const glm::dvec3 pos(light.position);
    const glm::dmat4 proj =
        glm::perspective(std::numbers::pi / 2.0, 1.0, double(light.shadow.x), double(light.shadow.y));
    return proj * glm::lookAt(pos, pos + forward, up);
}

glm::vec2 shadowMapUv(const GpuLightCpu& light, int face, const glm::dvec3& p) {
    const glm::dvec4 clip = shadowMapMatrix(light, face) * glm::dvec4(p, 1.0);
    return glm::vec2(glm::dvec2(clip) / clip.w * 0.5 + 0.5);
}

ShadowMapWalk walkShadowMap(const ShadowMaps& maps, const GpuLightCpu& light, const glm::dvec3& w, double tEnd) {
    VIZ_CHECK(light.info.z >= 0, "walkShadowMap: the light has no shadow map");
    ShadowMapWalk walk;
    const int n = maps.sizeOf(light);
    // Pieces of constant texel with their lit part, in order of t.
    struct Piece {
        double a, b;
        int face;
        bool lit;
    };
    std::vector<Piece> pieces;
    const int faces = isCube(light) ? 6 : 1;
    for (int face = 0; face < faces; ++face) {
        const ClipLine c = clipLine(shadowMapMatrix(light, face), w);
        double lo = 0.0, hi = tEnd;
        if (!clipToFrustum(c, lo, hi)) continue;
        walk.stretches.push_back({lo, hi, face});
        std::vector<double> cuts = {lo, hi};
        texelCuts(c, 0, n, lo, hi, cuts);
        texelCuts(c, 1, n, lo, hi, cuts);
        std::sort(cuts.begin(), cuts.end());
        const std::vector<float>& texels = maps.texels(light, face);
        for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
            const double ta = cuts[k], tb = cuts[k + 1];
            if (!(tb > ta)) continue;
            // The texel of the piece, from its middle (nearest texel, as the lookup; GL row 0 at ndc.y = -1).
            const glm::dvec4 q = c.at(0.5 * (ta + tb));
            const glm::dvec2 ndc = glm::dvec2(q) / q.w;
            const int i = std::clamp(int(std::floor((ndc.x * 0.5 + 0.5) * n)), 0, n - 1);
            const int j = std::clamp(int(std::floor((ndc.y * 0.5 + 0.5) * n)), 0, n - 1);
            const double stored = double(texels[std::size_t(j) * std::size_t(n) + std::size_t(i)]);
            double la = 0.0, lb = 0.0;
            if (!litPart(light, w, n, stored, ta, tb, la, lb)) {
                pieces.push_back({ta, tb, face, false});
                continue;
            }
            if (la > ta) pieces.push_back({ta, la, face, false});
            pieces.push_back({la, lb, face, true});
            if (tb > lb) pieces.push_back({lb, tb, face, false});
        }
    }
    std::sort(walk.stretches.begin(), walk.stretches.end(),
              [](const MapStretch& x, const MapStretch& y) { return x.t0 < y.t0; });
    std::sort(pieces.begin(), pieces.end(), [](const Piece& x, const Piece& y) { return x.a < y.a; });
    if (pieces.empty()) return walk;
    walk.startsLit = pieces.front().lit;
    bool lit = walk.startsLit;
    for (const Piece& p : pieces) {
        if (p.lit == lit) continue;
        walk.transitions.push_back({p.a, p.face, lit});
        lit = p.lit;
    }
    return walk;
}

std::vector<ViewMarker> shadowMapMarkers(const ShadowMaps& maps, const GpuLightCpu& light, const glm::dvec3& w,
                                         double tEnd) {
    const ShadowMapWalk walk = walkShadowMap(maps, light, w, tEnd);
    const bool cube = isCube(light);
    std::vector<ViewMarker> marks;
    for (const MapStretch& s : walk.stretches) {
        ViewMarker m;
        m.from = shadowMapUv(light, s.face, s.t0 * w);
        m.to = shadowMapUv(light, s.face, s.t1 * w);
        m.label = stretchLabel(s.t0, s.t1, !walk.startsLit && &s == &walk.stretches.front());
        m.layer = cube ? s.face : -1;
        marks.push_back(std::move(m));
    }
    for (const MapTransition& tr : walk.transitions) {
        ViewMarker m;
        m.from = m.to = shadowMapUv(light, tr.face, tr.t * w);
        m.label = transitionLabel(tr.entersShadow, tr.t);
        m.layer = cube ? tr.face : -1;
        marks.push_back(std::move(m));
    }
    return marks;
}

int shadowMapIndexOf(const std::string& id, const std::string& prefix) {
    const std::string base = prefix + ".shadow_map";
    if (id == base) return 0;
    if (id.size() <= base.size() + 1 || id.compare(0, base.size() + 1, base + ".") != 0) return -1;
    const std::string number = id.substr(base.size() + 1);
    if (number.empty() || number.size() > 6 || !std::all_of(number.begin(), number.end(), [](char c) { return c >= '0' && c <= '9'; })) return -1;
    const int n = std::stoi(number);
    return n > 0 ? n : -1;
}

}  // namespace viz::render
