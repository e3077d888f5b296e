// Linked-cursor marks in a light's shadow map: a camera pixel's eye ray projected into the map (spot and
// directional: the 2D map; point lights and VPLs: each cube face it crosses) and the points where it
// passes from lit to shadowed and back according to the map itself, i.e. the nearest-texel comparison and
// bias of shaders/common/shadow_map.glsl evaluated exactly, piece by piece, on the CPU against a readback
// of the map. Everything is eye-relative world space (the eye is the origin, as on the GPU).
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "debug/technique.h"
#include "render/host_device.h"
#include "render/shadow_maps.h"

namespace viz::render {

// Eye-relative world -> clip space of a light's map: the shadow matrix (spot, directional; face ignored)
// or the perspective of cube face `face` (0..5 = +X -X +Y -Y +Z -Z), as ShadowMaps::build rendered it.
glm::dmat4 shadowMapMatrix(const GpuLightCpu& light, int face);

// The part [t0, t1] of the eye ray that lies in one face's frustum (face 0 for 2D maps).
struct MapStretch {
    double t0 = 0.0, t1 = 0.0;
    int face = 0;
};

// A lit/shadow change along the ray: at t the ray enters shadow (lit before) or leaves it.
struct MapTransition {
    double t = 0.0;
    int face = 0;
    bool entersShadow = true;
};

struct ShadowMapWalk {
    std::vector<MapStretch> stretches;       // sorted by t; none when the ray misses the map
    std::vector<MapTransition> transitions;  // sorted by t, strictly inside the stretches' span
    bool startsLit = true;                   // the state at the first stretch's start
};

// Walks the eye ray p(t) = t w (w unit, eye-relative), t in [0, tEnd], through the map of `light`
// (which must have one: light.info.z >= 0): clipped to each face's frustum, cut at texel boundaries, and
// in each texel the set where d(p) <= stored + shadow.w + shadow.z * footprint solved in closed form
// (a quadratic in t for distance maps, linear for the directional depth).
ShadowMapWalk walkShadowMap(const ShadowMaps& maps, const GpuLightCpu& light, const glm::dvec3& w, double tEnd);

// Data uv of eye-relative point p in face `face` of the light's map: [0,1]^2, v = 0 at the map's GL row 0
// (ndc.y = -1), the convention of ViewMarker. Meaningless outside the face's frustum.
glm::vec2 shadowMapUv(const GpuLightCpu& light, int face, const glm::dvec3& p);

// The marks for the shadow-map intermediate of `light`: one segment per stretch ("eye ray t=a..b"), then
// a point per transition ("enters shadow t=3.21" / "leaves shadow t=4.05"). Cube marks carry the face
// as their layer. Empty when the ray misses the map.
std::vector<ViewMarker> shadowMapMarkers(const ShadowMaps& maps, const GpuLightCpu& light, const glm::dvec3& w,
                                         double tEnd);

// N for `<prefix>.shadow_map` (0) and `<prefix>.shadow_map.N` (ShadowMaps::publish); -1 for other ids.
int shadowMapIndexOf(const std::string& id, const std::string& prefix);

}  // namespace viz::render
