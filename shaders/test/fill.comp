#version 450 core
// Writes (testValue, 2 * testValue, x, y) into an rgba32f image, using two included files that both
// include values.glsl (exercises the include resolver and its once-only rule).
#include "test/values.glsl"
#include "test/twice.glsl"

layout(local_size_x = 4, local_size_y = 4) in;
layout(rgba32f, binding = 0) uniform writeonly image2D uOutput;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, imageSize(uOutput)))) return;
    imageStore(uOutput, texel, vec4(testValue(texel), testValueTwice(texel), texel));
}
