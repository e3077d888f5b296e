// Shared test function for gl_runtime_test: the value a compute shader writes at texel (x, y).
// The test computes the same formula on the CPU: x + 100 * y + 0.5.
#ifndef TEST_VALUES_GLSL
#define TEST_VALUES_GLSL

float testValue(ivec2 texel) { return float(texel.x) + 100.0 * float(texel.y) + 0.5; }

#endif
