#version 450 core
// vsv/pack.comp: four 32-bit words of the voxelization (R32UI layers 4l .. 4l + 3) -> one RGBA32UI texel
// of layer l of the epipolar grid (128 phi bits per texel, bit k = bit k & 31 of component k >> 5).
layout(local_size_x = 8, local_size_y = 8) in;

layout(r32ui, binding = 0) uniform readonly uimage2DArray uWords;
layout(rgba32ui, binding = 1) uniform writeonly uimage2DArray uGrid;
uniform ivec3 uSize;  // texels to pack, from uOrigin: (nAlpha, nTheta, nPhi / 128) for one grid
uniform ivec2 uOrigin;

void main() {
    ivec3 p = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(p, uSize))) return;
    p.xy += uOrigin;
    uvec4 v;
    for (int c = 0; c < 4; ++c) v[c] = imageLoad(uWords, ivec3(p.xy, 4 * p.z + c)).r;
    imageStore(uGrid, p, v);
}
