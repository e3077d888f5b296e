#version 450 core
// polyvol/clamp.comp: L_air = max(0, signed total). The exact sum is never negative; the computed one can
// be, by a few 1e-5 where the terms of one ray round or approximate the angular factor differently
// (README, "Precision"). The signed total itself stays published unclamped.
layout(local_size_x = 8, local_size_y = 8) in;

layout(rgba32f, binding = 0) uniform readonly image2D uTotal;
layout(rgba32f, binding = 1) uniform writeonly image2D uAirlight;
uniform ivec2 uSize;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(texel, uSize))) return;
    imageStore(uAirlight, texel, vec4(max(imageLoad(uTotal, texel).rgb, vec3(0.0)), 1.0));
}
