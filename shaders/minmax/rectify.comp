#version 450 core
// minmax/rectify.comp: the rectified shadow map S[alpha, gamma] (Chen et al. 2011, section 3.2). Texel
// (column j, row i) is the light ray gamma_j = gammaLo + (j + 1/2) width in slice alpha_i; every point of a
// light ray projects onto one shadow-map texel (spot: the ray leaves the map's centre of projection;
// directional: the map is orthographic along the ray; point: the ray's direction picks one cube texel),
// so one nearest lookup gives the ray's occluder. Point lights (EPIPOLAR_POINT) read their row's own
// gamma range (minmax/gamma_range.comp).
// S = beta of the occluder, after the same bias as shadowVisibility (common/shadow_map.glsl), so that
// "beta < S" and shadowVisibility agree for every point of the ray.
layout(local_size_x = 64, local_size_y = 1) in;

#include "common/constants.glsl"
#include "common/host_device.glsl"
#include "common/lights.glsl"
#include "common/shadow_map.glsl"
#include "minmax/epipolar.glsl"

layout(r32f, binding = 0) uniform writeonly image2D uRectified;
uniform int uLight;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (texel.x >= uColumns || texel.y >= uSlices) return;
    GpuLight L = gLights[uLight];
    selectRow(texel.y);
    float alpha = sliceAlpha(texel.y);
    float gamma = gammaOfColumn(float(texel.x) + 0.5);
    float S = kUnblocked;
#ifdef EPIPOLAR_POINT
    if (uKind == kKindPoint) {
        // The light ray's direction picks one texel of the cube (every point of the ray projects onto it);
        // the same bias as shadowVisibility for a cube: footprint d / size, so lit when
        // d <= (stored + w) / (1 - z / size).
        vec3 dir = -cos(gamma) * uAxis + sin(gamma) * slicePerpendicular(alpha);
        float stored = cubeLookup(uShadowCube, L.info.z, dir);
        float threshold = (stored + L.shadow.w) / (1.0 - L.shadow.z / float(textureSize(uShadowCube, 0).x));
        imageStore(uRectified, texel, vec4(occluderBeta(gamma, threshold)));
        return;
    }
#endif
    if (uKind == kKindSpot && (gamma <= 0.0 || gamma >= kPi)) {
        S = kOutsideCone;
    } else {
        vec3 p = lightRayPoint(alpha, gamma);
        vec4 clip = L.shadowMatrix * vec4(p, 1.0);
        vec2 ndc = clip.xy / clip.w;
        bool inside = clip.w > 0.0 && all(lessThanEqual(abs(ndc), vec2(1.0)));
        // Spot: no light leaves the cone (A_spot = 0): shadowed for the tree, nothing to integrate.
        bool dark = uKind == kKindSpot && spotAttenuation(L, p - L.position.xyz) == 0.0;
        if (dark) {
            S = kOutsideCone;
        } else if (inside) {
            // The rectified map keeps the surface lookup's footprint bias (and the traverse reads
            // shadowVisibility): it is sampled at discrete gamma columns, and without the bias
            // (depth-range-1e6: 2000-unit texels) the column spacing shadowed the air over lit receivers
            // (relative L2 0.43).
            float stored;
            S = occluderBeta(gamma, shadowLitLimit2D(L, ndc, 1.0, stored));
        }
    }
    imageStore(uRectified, texel, vec4(S));
}
