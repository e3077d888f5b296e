#version 450 core
// Includes a file with a syntax error; the error must be reported in broken_syntax.glsl.
#include "test/values.glsl"
#include "test/broken_syntax.glsl"
layout(local_size_x = 1) in;
void main() {}
