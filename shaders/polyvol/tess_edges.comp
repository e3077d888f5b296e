#version 450 core
// polyvol/tess_edges.comp: the edge map that decides where adaptive tessellation refines. For each texel
// of the map (a cube: of face uFace), of the values that are affine in the texel wherever the volume's
// vertices lie on one plane: a directional map's depths, and the reciprocal depths 1/z along the axis of a
// spot map or a cube face (perspective; Billeter et al. differentiate the depth buffer, which is affine in
// 1/z too). Neighbours are clamped at the border. The measure is scaled to a depth (directional: as is;
// perspective: times z^2 at the texel, the depth change a change of 1/z makes there) and divided by the
// map's range of stored values, so the threshold has no units:
//   uMeasure 0, Billeter et al. section 4.1: the Laplacian |4 c - (left + right + down + up)|. It is zero
//       wherever the second differences along x and y cancel, on a plane but also on a saddle (z = xy,
//       z = x^2 - y^2), which coarse quads then flatten.
//   uMeasure 1 (ours): the sum of the absolute second differences along x, y and both diagonals. It is at
//       least the Laplacian (every vertex that measure keeps is kept) and zero only where the vertices lie
//       on a plane (all second differences of an affine function vanish; those of any quadratic that is
//       not affine do not all vanish).
// Perspective maps: a texel whose neighbourhood mixes vertices at the light (dark spot texels, depth 0)
// with others is an edge (the maximum); one with all of them at the light, or all of them empty (the
// sphere of empty texels, beyond every surface the camera sees), is flat.
layout(local_size_x = 8, local_size_y = 8) in;

#include "polyvol/volume_grid.glsl"

layout(r16f, binding = 0) uniform writeonly image2D uEdges;  // the layer of face uFace
uniform int uFace;     // 0 for a 2D map; a cube's face 0..5 (neighbours clamped at the face's border)
uniform float uRange;  // far - near of the stored values (scene units)
uniform int uMeasure;  // 0: Laplacian (the paper); 1: absolute second differences (ours)

const float kMaxEdge = 6.0e4;  // r16f: keep it finite

void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, ivec2(uMapSize)))) return;
    GpuLight L = gLights[uLightIndex];
    ivec2 lo = max(t - 1, ivec2(0)), hi = min(t + 1, ivec2(uMapSize - 1));
    // The 3 x 3 neighbourhood, row by row from (lo.x, lo.y); z[4] is the texel itself.
    // The Laplacian reads the texel and its four edge neighbours; the second differences all nine.
    const int kLaplacianMask = (1 << 1) | (1 << 3) | (1 << 4) | (1 << 5) | (1 << 7);
    int used = uMeasure == 0 ? kLaplacianMask : 511;
    float z[9];
    int atLight = 0, empty = 0, count = 0;
    for (int k = 0; k < 9; ++k) {
        z[k] = 1.0;  // unread (the Laplacian's corners): never used
        if ((used & (1 << k)) == 0) continue;
        ivec2 o = ivec2(k % 3, k / 3);
        ivec2 q = ivec2(o.x == 0 ? lo.x : o.x == 1 ? t.x : hi.x, o.y == 0 ? lo.y : o.y == 1 ? t.y : hi.y);
        z[k] = gridAxisDepth(L, uFace, q.x, q.y);
        ++count;
        if (storedValue(uFace, q.x, q.y) >= 1.0e29) ++empty;
        else if (!(z[k] > 0.0)) ++atLight;
    }
    float scale = 1.0;
    if (uMode != kModeDirectional) {
        // All at the light, or all empty (a sphere beyond every surface, so beyond every pixel's d, where
        // crossings add nothing): flat. Some at the light: an edge.
        if (atLight == count || empty == count || atLight > 0) {
            imageStore(uEdges, t, vec4(atLight > 0 && atLight < count ? kMaxEdge : 0.0));
            return;
        }
        // z_c / z_k = z_c (1 / z_k): the reciprocal depths in units of the texel's own, so the sums below
        // stay finite (every neighbour enters with the same sign) and times z_c they are a depth.
        scale = z[4];
        float c = z[4];
        for (int k = 0; k < 9; ++k) z[k] = c / z[k];
    }
    float c = z[4], l = z[3], r = z[5], d = z[1], u = z[7];
    float e;
    if (uMeasure == 0) {
        e = abs(4.0 * c - (l + r + d + u));
    } else {
        e = abs(l + r - 2.0 * c) + abs(d + u - 2.0 * c) + abs(z[0] + z[8] - 2.0 * c) + abs(z[6] + z[2] - 2.0 * c);
    }
    e *= scale / uRange;
    imageStore(uEdges, t, vec4(isnan(e) ? kMaxEdge : min(e, kMaxEdge)));
}
