#version 450 core
// Shadow-map pass: writes the linear distance a shadow map stores (shadowDepth() of
// common/shadow_map.glsl) for the nearest surface (depth-tested): |p - uLightPosition|, or dot(p,
// uLightDirection) for a directional light (uDirectional = 1). Light data come as uniforms rather than
// from the light SSBO: one fewer buffer read per fragment. Input: eye-relative position (scene.vert).

#include "common/work_counters.glsl"

uniform vec3 uLightPosition;
uniform vec3 uLightDirection;
uniform int uDirectional;

in vec3 vPosition;
in vec3 vNormal;
in vec2 vUv;
flat in uint vMaterial;

layout(location = 0) out float oDistance;

void main() {
    WORK_COUNT(kWorkFragments, 1);
    oDistance = uDirectional != 0 ? dot(vPosition, uLightDirection) : length(vPosition - uLightPosition);
}
