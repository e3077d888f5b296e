// Includes values.glsl again; the loader must expand it only once (testValue would be redefined).
#include "test/values.glsl"

float testValueTwice(ivec2 texel) { return 2.0 * testValue(texel); }
