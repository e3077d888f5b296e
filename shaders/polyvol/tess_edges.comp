#version 450 core
// polyvol/tess_edges.comp: the edge map that decides where adaptive tessellation refines. For each texel
// of the shadow map, of the distances (spot) or depths (directional) at which the light volume puts its
// vertices (dark spot texels at 0, empty texels at the far value; neighbours clamped at the border),
// divided by the map's range of stored values so the threshold has no units:
//   uMeasure 0, Billeter et al. section 4.1: the Laplacian |4 c - (left + right + down + up)|. It is zero
//       wherever the second differences along x and y cancel, on a plane but also on a saddle (z = xy,
//       z = x^2 - y^2), which coarse quads then flatten.
//   uMeasure 1 (ours): the sum of the absolute second differences along x, y and both diagonals. It is at
//       least the Laplacian (every vertex that measure keeps is kept) and zero only where the vertices lie
//       on a plane in texel space (all second differences of a plane vanish; those of any quadratic that
//       is not a plane do not all vanish).
layout(local_size_x = 8, local_size_y = 8) in;

#include "polyvol/volume_grid.glsl"

layout(r16f, binding = 0) uniform writeonly image2D uEdges;
uniform float uRange;  // far - near of the stored values (scene units)
uniform int uMeasure;  // 0: Laplacian (the paper); 1: absolute second differences (ours)

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, ivec2(uMapSize)))) return;
    GpuLight L = gLights[uLightIndex];
    int last = uMapSize - 1;
    float c = gridDistance(L, 0, t.x, t.y);
    float l = gridDistance(L, 0, max(t.x - 1, 0), t.y);
    float r = gridDistance(L, 0, min(t.x + 1, last), t.y);
    float d = gridDistance(L, 0, t.x, max(t.y - 1, 0));
    float u = gridDistance(L, 0, t.x, min(t.y + 1, last));
    float e;
    if (uMeasure == 0) {
        e = abs(4.0 * c - (l + r + d + u));
    } else {
        ivec2 lo = max(t - 1, ivec2(0)), hi = min(t + 1, ivec2(last));
        float ll = gridDistance(L, 0, lo.x, lo.y), hh = gridDistance(L, 0, hi.x, hi.y);
        float lh = gridDistance(L, 0, lo.x, hi.y), hl = gridDistance(L, 0, hi.x, lo.y);
        e = abs(l + r - 2.0 * c) + abs(d + u - 2.0 * c) + abs(ll + hh - 2.0 * c) + abs(lh + hl - 2.0 * c);
    }
    imageStore(uEdges, t, vec4(min(e / uRange, 6.0e4)));  // r16f: keep it finite
}
