// Where a march along the eye ray puts sample i of n on a lit span (raymarch's march, minmax's brute-force
// march): its interval [x0, x1] (the intervals tile the span), its point t (offset u in (0, 1) inside the
// interval's share of the sampling variable) and its weight dt, the length of ray the sample stands for.
// Uniform in t (dt = the interval's length). With FAR_RAYS, a span longer than farSpan (a camera's zfar of
// 1e6 in a scene 10 units across: scene/ray_reach.h) would leave the scene with few samples or none, so it
// is sampled by the light instead: uniform in the angle the ray subtends at a point-like light
// (equiangular: t = t_P + h tan(theta), dt = dtheta r^2 / h, so E dt is flat away from shadows), or
// uniform in the transmittance 1 - exp(-sigma_t (t - t0)) for a directional light (dt = dq / (sigma_t
// (1 - q)) per share dq). Needs GpuLight (common/lights.glsl) and, for tailByTheLight, the shadow maps
// (common/shadow_map.glsl).
#ifndef MARCH_SAMPLES_GLSL
#define MARCH_SAMPLES_GLSL

#include "common/airlight_sample.glsl"

struct MarchSample {
    float x0, x1, t, dt;
};

MarchSample placeSample(GpuLight L, vec3 w, vec2 span, int i, int count, float u, float farSpan) {
    float n = float(count);
    float len = span.y - span.x;
    MarchSample m;
    m.dt = len / n;
    m.x0 = span.x + float(i) * m.dt;
    m.x1 = span.x + float(i + 1) * m.dt;
    m.t = span.x + (float(i) + u) * m.dt;
#ifdef FAR_RAYS
    if (len <= farSpan) return m;
    if (L.info.x == kLightDirectional) {
        float total = 1.0 - exp(-uSigmaT * len);  // the span's share of the transmittance
        if (uSigmaT * len < 1.0e-3) return m;     // nearly clear: uniform is the same
        float q0 = float(i) / n * total, q1 = float(i + 1) / n * total, q = (float(i) + u) / n * total;
        m.x0 = span.x - log(1.0 - q0) / uSigmaT;
        m.x1 = i + 1 == count ? span.y : span.x - log(1.0 - q1) / uSigmaT;
        m.t = clamp(span.x - log(1.0 - q) / uSigmaT, m.x0, m.x1);
        m.dt = total / (n * uSigmaT * (1.0 - q));
        return m;
    }
    RayLightGeometry g = rayLightGeometry(L.position.xyz, w);
    if (g.h < 1.0e-6 * len) return m;  // a ray through the light: no angle to spread the samples over
    float th0 = atan((span.x - g.tP) / g.h), th1 = atan((span.y - g.tP) / g.h);
    float dth = (th1 - th0) / n;
    m.x0 = i == 0 ? span.x : clamp(g.tP + g.h * tan(th0 + float(i) * dth), span.x, span.y);
    m.x1 = i + 1 == count ? span.y : clamp(g.tP + g.h * tan(th0 + float(i + 1) * dth), span.x, span.y);
    m.t = clamp(g.tP + g.h * tan(th0 + (float(i) + u) * dth), m.x0, m.x1);
    vec3 r = m.t * w - L.position.xyz;
    m.dt = dth * dot(r, r) / g.h;
#endif
    return m;
}

#ifdef FAR_RAYS
// L_air of light L over [span.x, span.y] from `count` samples placed by the light, each tested against
// the shadow map: the rest of a ray past slices' planes and vsv's grid under a far camera (FAR_TAIL).
vec3 tailByTheLight(GpuLight L, vec3 w, vec2 span, int count) {
    vec3 sum = vec3(0.0);
    if (span.y <= span.x) return sum;
    for (int i = 0; i < count; ++i) {
        MarchSample m = placeSample(L, w, span, i, count, 0.5, 0.0);
        vec3 x = m.t * w;
        float V = shadowVisibilityMedium(L, x);
        if (V > 0.0) sum += airlightSample(V, dot(directionToLight(L, x), w), unshadowedIrradiance(L, x, uSigmaT), m.t, m.dt);
    }
    return sum;
}
#endif

#endif  // MARCH_SAMPLES_GLSL
