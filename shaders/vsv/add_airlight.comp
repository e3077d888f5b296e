#version 450 core
// vsv/add_airlight.comp: uTarget += uExtra over the image (rgb; alpha 1). vsv and ivsv add the L_air of
// the other technique, which shades the lights they do not handle (techniques/vsv/add_airlight.h).
layout(local_size_x = 8, local_size_y = 8) in;

layout(rgba32f, binding = 0) uniform image2D uTarget;
layout(binding = 0) uniform sampler2D uExtra;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(uTarget)))) return;
    vec3 sum = imageLoad(uTarget, p).rgb + texelFetch(uExtra, p, 0).rgb;
    imageStore(uTarget, p, vec4(sum, 1.0));
}
