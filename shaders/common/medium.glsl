// The medium's coefficients, the one declaration every shader includes (C++: render::MediumBlock, which
// fills the block as a GpuMedium; see host_device.glsl). Per scene unit: uSigmaS scattering, uSigmaT
// extinction; uG is the Henyey-Greenstein asymmetry.
#ifndef COMMON_MEDIUM_GLSL
#define COMMON_MEDIUM_GLSL

#include "common/host_device.glsl"

layout(std140, binding = kBindingMedium) uniform GpuMediumBlock {
    float uSigmaS;
    float uSigmaT;
    float uG;
};

#endif
