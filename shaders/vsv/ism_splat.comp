#version 450 core
// vsv/ism_splat.comp: imperfect shadow maps. Point i of the scene's point cloud belongs to VPL
// i mod uVplCount (each VPL sees its own sparse subset); it is projected into that VPL's paraboloid
// tile and keeps the nearest distance per texel (atomic min on the float's bits: non-negative floats
// order like their bit patterns).
layout(local_size_x = 64) in;

#include "vsv/ism.glsl"
#include "vsv/ivsv_vpls.glsl"

layout(std430, binding = 5) readonly buffer Points { vec4 gPoints[]; };
layout(r32ui, binding = 0) uniform uimage2D uIsmBits;
uniform int uPointCount;
uniform int uVplCount;
uniform int uTileSize;

void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= uPointCount) return;
    IvsvVpl v = gVpls[i % uVplCount];
    vec3 d = gPoints[i].xyz - v.position.xyz;
    float r = length(d);
    if (r <= 0.0) return;
    ivec2 texel;
    if (!ismTexel(d / r, v.tangent.xyz, v.bitangent.xyz, v.normal.xyz, v.tile.zw, uTileSize, texel)) return;
    imageAtomicMin(uIsmBits, texel, floatBitsToUint(r));
}
