#version 450 core
// probe/alu.comp: the probe's arithmetic (probe/alu.glsl) once per pixel as a compute pass.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba32f) uniform writeonly image2D uOut;
#include "probe/alu.glsl"

void main() {
    ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(pixel, imageSize(uOut)))) return;
    imageStore(uOut, pixel, probeAlu(pixel));
}
