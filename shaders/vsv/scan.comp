#version 450 core
// vsv/scan.comp: one pass of the parallel prefix OR along alpha (Hillis-Steele): out[a] = in[a] |
// in[a - uOffset]. After passes with offsets 1, 2, 4, ... >= nAlpha, texel a holds the OR of texels
// 0..a: a light ray's occluder bit is extruded to every alpha beyond it (away from the light).
// uSegment > 0 restarts the scan every uSegment texels (several epipolar spaces side by side).
layout(local_size_x = 8, local_size_y = 8) in;
#include "common/work_counters.glsl"

layout(rgba32ui, binding = 0) uniform readonly uimage2DArray uIn;
layout(rgba32ui, binding = 1) uniform writeonly uimage2DArray uOut;
uniform ivec3 uSize;    // texels scanned, from uOrigin
uniform ivec2 uOrigin;  // a multiple of uSegment along x
uniform int uOffset;
uniform int uSegment;

void main() {
    ivec3 p = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(p, uSize))) return;
    p.xy += uOrigin;
    uvec4 v = imageLoad(uIn, p);
    int inSegment = uSegment > 0 ? p.x % uSegment : p.x;
    WORK_COUNT(kWorkVoxelsRead, inSegment >= uOffset ? 2 : 1);
    WORK_COUNT(kWorkVoxelsWritten, 1);
    if (inSegment >= uOffset) v |= imageLoad(uIn, p - ivec3(uOffset, 0, 0));
    imageStore(uOut, p, v);
}
