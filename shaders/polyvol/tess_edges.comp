#version 450 core
// polyvol/tess_edges.comp: the Laplacian edge map of Billeter et al. section 4.1. For each texel of the
// shadow map, |4 c - (left + right + down + up)| of the distances (spot) or depths (directional) at which
// the light volume puts its vertices (dark spot texels at 0, empty texels at the far value; neighbours
// clamped at the border), divided by the map's range of stored values so the threshold has no units.
// Zero where the vertices lie on a plane in texel space (orthographic maps of flat receivers).
layout(local_size_x = 8, local_size_y = 8) in;

#include "polyvol/volume_grid.glsl"

layout(r16f, binding = 0) uniform writeonly image2D uEdges;
uniform float uRange;  // far - near of the stored values (scene units)

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
    float lap = abs(4.0 * c - (l + r + d + u)) / uRange;
    imageStore(uEdges, t, vec4(min(lap, 6.0e4)));  // r16f: keep it finite
}
