#version 450 core
// The error is in this file, after an include: line numbering must resume correctly after it.
#include "test/values.glsl"

layout(local_size_x = 1) in;
void main() {
    float ok = testValue(ivec2(0));
    int wrong = undefinedName;  // DELIBERATE ERROR: undeclared identifier
}
