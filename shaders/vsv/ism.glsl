// Imperfect shadow maps: one tile per VPL in an atlas, the VPL's hemisphere mapped by a paraboloid
// (mirror of vsv::paraboloid in viz/techniques/vsv/vpl_sampling.h). A texel holds the distance to the
// VPL of the nearest point splatted there (0 = no sample: a hole until push-pull fills it).
#ifndef VSV_ISM_GLSL
#define VSV_ISM_GLSL

// Unit direction in the VPL's frame (x, y, n) -> texel of its tile (origin tile0, size tileSize);
// false when the direction is outside the hemisphere.
bool ismTexel(vec3 dir, vec3 x, vec3 y, vec3 n, ivec2 tile0, int tileSize, out ivec2 texel) {
    float z = dot(dir, n);
    if (z <= 0.0) return false;
    vec2 uv = vec2(dot(dir, x), dot(dir, y)) / (1.0 + z);
    texel = tile0 + clamp(ivec2(floor((uv * 0.5 + 0.5) * float(tileSize))), ivec2(0), ivec2(tileSize - 1));
    return true;
}

#endif  // VSV_ISM_GLSL
