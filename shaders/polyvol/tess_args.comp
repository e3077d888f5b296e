#version 450 core
// polyvol/tess_args.comp: one invocation between refinement steps. uDraw = 0: the quads appended by the
// last step become the next step's input (indirect dispatch of ceil(n / 64) groups); uDraw = 1: the
// indirect draw of the emitted triangles (clamped to the key buffer).
layout(local_size_x = 1) in;

uniform int uDraw;
uniform uint uListCapacity;
uniform uint uKeyCapacity;

layout(std430, binding = 4) buffer Counters {
    uint inCount;
    uint outCount;
    uint triangles;
    uint overflow;
    uint dispatchArgs[3];
    uint drawArgs[4];
};

void main() {
    if (uDraw == 0) {
        inCount = min(outCount, uListCapacity);
        outCount = 0u;
        dispatchArgs[0] = (inCount + 63u) / 64u;
        dispatchArgs[1] = 1u;
        dispatchArgs[2] = 1u;
    } else {
        drawArgs[0] = 3u * min(triangles, uKeyCapacity / 3u);
        drawArgs[1] = 1u;
        drawArgs[2] = 0u;
        drawArgs[3] = 0u;
    }
}
