#version 450 core
// vsv/ivsv_gather.comp: airlight of many VPLs from their voxelized shadow volumes (one grid tile each,
// 128 phi bits = one texel per eye ray). Per pixel and VPL: the eye ray's (alpha, theta) in that VPL's
// epipolar space picks the texel(s), the phi bits up to the fragment are the visibility samples, and
// the airlight is a midpoint quadrature in the VPL's angle phi with one node per uChunkBits bits, each
// node weighted by the lit fraction of its bits (COMBINE_EXACT), or the lit fraction of all bits times
// the unshadowed quadrature (the factorisation).
// Each VPL is a cosine-lobe point light of intensity L_e dA along its normal (render/gpu_lights.h).
// Variants: the invocation's pixel is uScale * id of the full image (uScale = 2 for the quarter-resolution
// gather); with 3x3 interleaving (uVplStride = 9) a pixel gathers one ninth of the VPLs (the subset of
// its place in the 3x3 pattern), scaled by 9, and a bilateral filter recombines the nine. DEINTERLEAVE:
// the invocations run over the nine sub-images of the pattern side by side (sub-image (bx, by) holds the
// pixels (3 u + bx, 3 v + by)), each uSubSize invocations, a whole number of work groups, so a work group's
// pixels all gather the same VPLs and read the same grid tiles; each pixel computes exactly what it would
// in screen order.
// EPIPOLE (the paper's rule, Wyman and Dai 2013 Sec. 5): within one alpha cell of a VPL's epipole its grid
// is degenerate (one texel holds every ray there), so the ray's visibility is one test instead: toward the
// VPL, lit when the fragment lies beyond the VPL's foot point on the ray, less 4 alpha cells of depth (the
// emitter the VPL sits on is not an occluder); away from it, lit when the eye sees the VPL (its shadow map
// at the eye). The VPL's flags (extra.y toward, extra.z away) say which epipole its grid reaches.
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/host_device.glsl"
#include "common/lights.glsl"
#include "common/shadow_map.glsl"
#include "vsv/ism.glsl"
#include "common/airlight.glsl"
#include "vsv/bits128.glsl"
#include "common/camera_ray.glsl"
#include "vsv/ivsv_vpls.glsl"

layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;
layout(binding = kFirstFreeTextureUnit + 1) uniform sampler2D uIsm;  // filled atlas (EPIPOLE, not CUBE)
layout(rgba32ui, binding = 0) uniform readonly uimage2DArray uGrid;
layout(rgba32f, binding = 1) uniform image2D uAirlight;   // at the invocation's resolution
layout(r32f, binding = 2) uniform image2D uVisibility;    // mean lit fraction over the VPLs gathered
layout(std430, binding = 6) buffer PickContributions { vec4 gPick[]; };

uniform ivec2 uOutSize;   // the output image's size (full or quarter resolution)
uniform ivec2 uSubSize;   // DEINTERLEAVE: invocations per sub-image
uniform int uScale;
uniform ivec3 uCells;
uniform int uFirstVpl;
uniform int uVplCount;    // VPLs [uFirstVpl, uFirstVpl + uVplCount)
uniform int uVplStride;   // 1 or 9
uniform int uPhaseShift;  // added to the 3x3 subset index, mod 9 (subsets=per-frame: the frame index)
#include "common/medium.glsl"  // uSigmaS, uSigmaT, uG
#include "common/airlight_sample.glsl"
#include "common/work_counters.glsl"
uniform int uChunkBits;
uniform float uDiscScale;  // 1: vpl_kernel=cell (a grid VPL is its cell, a Halton VPL a disc of its area), 0: points
uniform int uAccumulate;
uniform ivec2 uPick;      // full-resolution pixel whose per-VPL contributions go to gPick (-1: none)
uniform int uTileSize;    // ISM tile size (EPIPOLE)

// Whether the eye (the origin) sees VPL v: its shadow map toward the eye against the eye's distance.
float eyeVisibility(IvsvVpl v) {
    vec3 dir = -v.position.xyz;
    float D = length(dir);
    if (!(D > 0.0)) return 1.0;
    dir /= D;
#ifdef CUBE
    float r = cubeLookup(uShadowCube, v.extra.x, dir);
    if (r >= 1.0e29) r = 0.0;
#else
    ivec2 texel;
    if (!ismTexel(dir, v.tangent.xyz, v.bitangent.xyz, v.normal.xyz, v.tile.zw, uTileSize, texel)) return 1.0;
    float r = texelFetch(uIsm, texel, 0).r;
#endif
    return r <= 0.0 || r >= 0.98 * D ? 1.0 : 0.0;  // no sample there (a hole that stayed empty): lit
}

// Lit (clear) fraction of bits [first, last) of a column.
float litBits(uvec4 c, int first, int last) {
    return last > first ? 1.0 - float(countBits(c, first, last)) / float(last - first) : 1.0;
}

void main() {
    ivec2 id = ivec2(gl_GlobalInvocationID.xy);  // the output texel
#ifdef DEINTERLEAVE
    id = 3 * (id % uSubSize) + id / uSubSize;
#endif
    if (any(greaterThanEqual(id, uOutSize))) return;
    ivec2 pixel = min(id * uScale, uSize - 1);
    vec3 w = pixelRay(pixel);
    float d = texelFetch(uDistance, pixel, 0).r;
    int phase = uVplStride == 9 ? ((pixel.x % 3) + 3 * (pixel.y % 3) + uPhaseShift) % 9 : 0;
    bool picked = pixel == uPick;

    vec3 total = vec3(0.0);
    float fractionSum = 0.0;
    float gathered = 0.0;
    // Interleaving subset of VPL i: (i + i / 9) mod 9, not i mod 9: the base-3 Halton coordinate of
    // i mod 9 fixes v to one ninth of the emitter, which would give every pixel one horizontal strip.
    // The pixel walks its own subset only, in increasing index (the sum of testing every VPL and skipping
    // the others, without walking them): VPL i = 9q + m is in subset (m + q) mod 9, so each block q of
    // nine holds exactly one member, m = (phase - q) mod 9. Neighbouring pixels of a SIMD group then run
    // the same number of iterations, a ninth of the VPLs, instead of all of them.
    int lo = uFirstVpl, hi = uFirstVpl + uVplCount;
    int steps = uVplStride == 9 ? (hi + 8) / 9 - lo / 9 : uVplCount;
    for (int k = 0; k < steps; ++k) {
        int vi = lo + k;
        if (uVplStride == 9) {
            int q = lo / 9 + k;
            vi = 9 * q + (phase - q % 9 + 9) % 9;
            if (vi < lo || vi >= hi) continue;
        }
        IvsvVpl v = gVpls[vi];
        EpiSpace S = vplSpace(v, uCells);
        float alpha = epiAlphaOf(S, w);
        int ia = clamp(int(floor(epiAlphaCoord(S, alpha))), 0, uCells.x - 1);
        int j0, j1;
        float wTheta;
#ifdef INTERP
        epiThetaCells(S, epiThetaOf(S, w), true, j0, j1, wTheta);
#else
        epiThetaCells(S, epiThetaOf(S, w), false, j0, j1, wTheta);
#endif
        uvec4 c0 = imageLoad(uGrid, ivec3(v.tile.x + ia, v.tile.y + j0, 0));
        uvec4 c1 = imageLoad(uGrid, ivec3(v.tile.x + ia, v.tile.y + j1, 0));
        WORK_COUNT(kWorkVoxelsRead, 2);
        float phiD = epiPhiOnEyeRay(S, alpha, d);
        float kEnd = clamp((phiD - S.phi.x) / S.phi.y, 0.0, float(uCells.z));
        int lastBit = int(ceil(kEnd));

        // Quadrature in the light's angle phi: along the eye ray dt / r^2 = dphi / h (h = D sin alpha,
        // the VPL-ray distance), so the airlight integrand is bounded and smooth in phi, and the phi bits
        // are uniform in it. One midpoint node per uChunkBits bits; the node's visibility is the lit
        // fraction of its bits (theta-interpolated). With the triangle (eye, VPL, point):
        // t = D sin(phi) / sin(alpha + phi), r = D sin(alpha) / sin(alpha + phi), cos theta = cos(alpha + phi).
        float D = v.epiB.w;
        float sinA = sin(alpha);
        float h = max(D * sinA, 1.0e-4 * D);
        float sum = 0.0, unshadowed = 0.0;
        for (int first = 0; first < lastBit; first += uChunkBits) {
            int last = min(first + uChunkBits, lastBit);
            float phiA = S.phi.x + float(first) * S.phi.y;
            float phiB = min(S.phi.x + float(last) * S.phi.y, phiD);
            if (!(phiB > phiA)) break;
            float phiM = 0.5 * (phiA + phiB);
            float sn = sin(alpha + phiM);
            if (sn <= 0.0) break;
            float t = D * sin(phiM) / sn;
            float r = D * sinA / sn;
            vec3 x = t * w;
            // The VPL's angular factor in place of a point's 1/r^2 times r^2: cos(theta_e) for a point; a grid
            // VPL with vpl_kernel=cell is its cell (cellAngularFactor, common/solid_angle.glsl, as the shared
            // VPLs); a Halton VPL then stands for a disc of area dA, radius^2 eps2 = dA / pi: on its axis the
            // disc gives the point's 1/r^2 times r^2 / (r^2 + eps2), which bounds the spike of rays grazing a
            // VPL.
            float angular;
            if (uDiscScale > 0.0 && v.cellCorner.w > 0.0) {
                angular = cellAngularFactor(v.cellCorner.xyz - x, v.cellU.xyz, v.cellV.xyz, v.normal.xyz,
                                            v.cellCorner.w, r * r);
            } else {
                float lobe = max(0.0, dot(v.normal.xyz, (x - v.position.xyz) / max(r, 1.0e-6)));
                angular = lobe * (r * r / (r * r + uDiscScale * v.weight.w));
            }
            // The sample in phi: dt = r^2 / h dphi cancels the VPL's 1/r^2, so its irradiance times that
            // Jacobian is angular exp(-sigma_t r) / h (the VPL's intensity is applied per VPL, after the sum).
            float f = airlightSample(1.0, cos(alpha + phiM), vec3(angular * exp(-uSigmaT * r) / h), t, phiB - phiA).x;
            float vis = mix(litBits(c0, first, last), litBits(c1, first, last), wTheta);
            sum += vis * f;
            unshadowed += f;
        }
        float fraction = mix(litBits(c0, 0, lastBit), litBits(c1, 0, lastBit), wTheta);
#ifndef COMBINE_EXACT
        sum = fraction * unshadowed;
#endif
#ifdef EPIPOLE
        bool towardCell = v.extra.y != 0 && alpha < S.alpha.x + S.alpha.y;
        bool awayCell = v.extra.z != 0 && alpha > S.alpha.x + (float(uCells.x) - 1.0) * S.alpha.y;
        if (towardCell || awayCell) {
            fraction = towardCell ? (d > dot(v.position.xyz, w) - 4.0 * D * S.alpha.y ? 1.0 : 0.0) : eyeVisibility(v);
            sum = fraction * unshadowed;
        }
#endif
        vec3 contribution = float(uVplStride) * sum * v.weight.rgb;
        total += contribution;
        fractionSum += fraction;
        gathered += 1.0;
        if (picked) gPick[vi] = vec4(sum * v.weight.rgb, fraction);
    }
    vec4 previous = uAccumulate != 0 ? imageLoad(uAirlight, id) : vec4(0.0);
    imageStore(uAirlight, id, vec4(previous.rgb + total, 1.0));
    if (uAccumulate == 0) imageStore(uVisibility, pixel, vec4(gathered > 0.0 ? fractionSum / gathered : 1.0));
}
