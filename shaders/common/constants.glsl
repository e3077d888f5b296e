// Numbers the shaders share, each defined once (a test keeps pi's digits out of every other file).
#ifndef COMMON_CONSTANTS_GLSL
#define COMMON_CONSTANTS_GLSL

const float kPi = 3.14159265358979323846;

#endif
