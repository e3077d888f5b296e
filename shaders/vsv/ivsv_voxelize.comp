#version 450 core
// vsv/ivsv_voxelize.comp: rectification of every VPL's shadow map into its own epipolar grid tile, all
// VPLs in one dispatch (z = VPL). Same per-ray rule as vsv/voxelize.comp; the occluder distance comes
// from the VPL's imperfect shadow-map tile (ISM) or, for mode=naive, from its cube shadow map (CUBE).
layout(local_size_x = 8, local_size_y = 8) in;

#include "common/host_device.glsl"
#include "common/lights.glsl"
#include "common/shadow_map.glsl"
#include "vsv/ism.glsl"
#include "vsv/ivsv_vpls.glsl"
#include "common/work_counters.glsl"

layout(r32ui, binding = 0) uniform coherent uimage2DArray uWords;  // 4 layers: 128 phi bits
layout(binding = kFirstFreeTextureUnit + 1) uniform sampler2D uIsm;  // filled atlas, level 0
uniform ivec3 uCells;  // (nAlpha, nTheta, 128)
uniform int uFirstVpl;
uniform int uTileSize;
uniform float uAlphaBias;
uniform float uPhiBias;

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    int k = id.x, j = id.y;
    if (k >= uCells.z || j >= uCells.y) return;
    IvsvVpl v = gVpls[uFirstVpl + id.z];
    EpiSpace S = vplSpace(v, uCells);
    float theta = epiThetaAtCell(S, float(j) + 0.5);
    float phi = S.phi.x + (float(k) + 0.5 + uPhiBias) * S.phi.y;
    if (!(phi > 0.0 && phi < kPi)) return;
    vec3 dir = epiLightRay(S, theta, phi);
    float r = 0.0;
#ifdef CUBE
    r = cubeLookup(uShadowCube, v.extra.x, dir);
    if (r >= 1.0e29) r = 0.0;
#else
    ivec2 texel;
    if (!ismTexel(dir, v.tangent.xyz, v.bitangent.xyz, v.normal.xyz, v.tile.zw, uTileSize, texel)) return;
    r = texelFetch(uIsm, texel, 0).r;
#endif
    if (r <= 0.0) return;
    float c = epiAlphaCoord(S, epiAlphaOnLightRay(S, phi, r)) - uAlphaBias;
    if (c >= float(uCells.x)) return;
    int cell = max(0, int(floor(c)));
    imageAtomicOr(uWords, ivec3(v.tile.x + cell, v.tile.y + j, k >> 5), 1u << uint(k & 31));
    WORK_COUNT(kWorkVoxelsWritten, 1);
}
