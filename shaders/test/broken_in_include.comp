#version 450 core
// Compiles an include that contains an error: the error must be reported in broken_include.glsl.
#include "test/values.glsl"
#include "test/broken_include.glsl"

layout(local_size_x = 1) in;
void main() {}
