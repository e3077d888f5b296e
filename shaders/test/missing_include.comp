#version 450 core
// Includes a file that does not exist: the loader must name this file and line.
#include "test/does_not_exist.glsl"
layout(local_size_x = 1) in;
void main() {}
