#version 450 core
// Counts the iterations a loop of uCount steps really runs (llvmpipe caps loops per invocation).
layout(local_size_x = 1) in;
layout(std430, binding = 0) buffer Out { uint counts[]; };
uniform int uCount;
uniform int uNested;  // 0: one loop of uCount; n > 0: uCount / n outer iterations of an inner loop of n
void main() {
    uint c = 0u;
    if (uNested == 0) {
        for (int i = 0; i < uCount; ++i) c += 1u;
    } else {
        for (int i = 0; i < uCount / uNested; ++i)
            for (int j = 0; j < uNested; ++j) c += 1u;
    }
    counts[0] = c;
}
