#version 450 core
// render/shadow_nearest.comp: the smallest distance stored in layers [uFirstLayer, uFirstLayer + uLayers)
// of a shadow-map array (a spot's map, or a point light's six cube faces), for ShadowMaps::nearest().
// Each invocation folds its texel of every layer, the work group folds in shared memory, and one
// atomicMin per group reaches the buffer. Distances are clamped to >= 0 first: non-negative floats order
// like their bit patterns, so the minimum is taken on uints.
layout(local_size_x = 16, local_size_y = 16) in;

layout(r32f, binding = 0) uniform readonly image2DArray uMaps;
uniform int uFirstLayer;
uniform int uLayers;
uniform int uSize;
layout(std430, binding = 0) buffer Nearest {
    uint gNearest;  // float bits; the caller fills it with its upper bound
};

shared uint sNearest;

void main() {
    if (gl_LocalInvocationIndex == 0u) sNearest = 0x7f7fffffu;  // FLT_MAX
    barrier();
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    uint nearest = 0x7f7fffffu;
    if (all(lessThan(p, ivec2(uSize)))) {
        for (int l = 0; l < uLayers; ++l) {
            float d = imageLoad(uMaps, ivec3(p, uFirstLayer + l)).r;
            nearest = min(nearest, floatBitsToUint(max(d, 0.0)));
        }
    }
    atomicMin(sNearest, nearest);
    barrier();
    if (gl_LocalInvocationIndex == 0u) atomicMin(gNearest, sNearest);
}
