#version 450 core
// vsv/ism_pushpull.comp: hole filling of the imperfect shadow maps on the atlas mip chain (tiles are
// powers of two, so level l of a tile is level l of the atlas at origin >> l).
//   uMode 0: convert the splatted bits (R32UI, all ones = empty) to distances at level 0 (0 = hole),
//            also into the "before push-pull" copy.
//   uMode 1 (pull): level uLevel + 1 = mean of the non-empty texels of its 2x2 children at uLevel.
//   uMode 2 (push): empty texels of uLevel take their parent's value at uLevel + 1, but only below level
//            uFillLevels: a hole is filled from a sample at most 2^uFillLevels texels away, and a wider one
//            (a direction that sees no geometry: open sky) stays 0, which the rectification reads as "no
//            occluder". Filling every hole made the sky an average of the surfaces around it: false
//            occluders over every open direction.
layout(local_size_x = 8, local_size_y = 8) in;

layout(r32ui, binding = 0) uniform readonly uimage2D uBits;
layout(r32f, binding = 1) uniform image2D uFine;    // level uLevel
layout(r32f, binding = 2) uniform image2D uCoarse;  // level uLevel + 1
layout(r32f, binding = 3) uniform writeonly image2D uBefore;
uniform int uMode;
uniform int uLevel;       // push: the level written
uniform int uFillLevels;  // push: levels up the pyramid a hole may take its value from
uniform ivec2 uSize;  // texels of the level the invocation writes

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, uSize))) return;
    if (uMode == 0) {
        uint b = imageLoad(uBits, p).r;
        float d = b == 0xffffffffu ? 0.0 : uintBitsToFloat(b);
        imageStore(uFine, p, vec4(d));
        imageStore(uBefore, p, vec4(d));
    } else if (uMode == 1) {
        float sum = 0.0;
        float n = 0.0;
        for (int c = 0; c < 4; ++c) {
            float d = imageLoad(uFine, 2 * p + ivec2(c & 1, c >> 1)).r;
            if (d > 0.0) {
                sum += d;
                n += 1.0;
            }
        }
        imageStore(uCoarse, p, vec4(n > 0.0 ? sum / n : 0.0));
    } else {
        float d = imageLoad(uFine, p).r;
        if (d <= 0.0 && uLevel < uFillLevels) imageStore(uFine, p, vec4(imageLoad(uCoarse, p / 2).r));
    }
}
