#version 450 core
// polyvol/volume.frag: one term of Billeter et al.'s equation 3. The fragment is where the eye ray
// through this pixel crosses the light volume's boundary; its point x (clamped to the surface distance d)
// contributes +L(0, x) when the ray leaves the lit volume there and -L(0, x) when it enters, so the sum
// over all crossings is the airlight of the lit parts of [0, d].
// uOriginAtSurface = 1 (precision mitigation, see README): each term is written relative to the surface,
// L(0, x) = L(0, d) - L(x, d); the fragment adds -s L(x, d) and the resolve adds c L(0, d) once per pixel
// and light, c = the signed crossing count. Crossings clamped to d then add exactly 0 instead of
// +-L(0, d) pairs that cancel in fp32.
// Rays next to the light (README): each term leaves out the ray's chord through the ball of radius
// uNearRadius around the light, which the resolve adds once per pixel.
// Outputs (additive blending): 0 signed total (rgb, a = signed crossing count of this light, consumed by
// the resolve), 1 sum of the positive terms, 2 sum of the negative terms (as positive values),
// 3 crossings (r = count, g = signed count over all lights: the crack detector's input; b = in front of the
// near plane, a = beyond the surface).

#include "polyvol/segment.glsl"

layout(binding = kFirstFreeTextureUnit) uniform sampler2D uDistance;  // Euclidean t of the first surface

uniform int uLightIndex;
uniform int uConstant;         // 1: crack detector, the integrand is 1 so each term is +-x
uniform int uOriginAtSurface;
uniform float uNear;           // the camera's znear: crossings nearer along the view exist only by the depth clamp
uniform float uNearRadius;     // radius of the ball around the light left to the resolve (0: none)

in vec3 vPosition;

layout(location = 0) out vec4 oTotal;
layout(location = 1) out vec4 oPositive;
layout(location = 2) out vec4 oNegative;
layout(location = 3) out vec4 oCrossings;

void main() {
    WORK_PIXEL(gl_FragCoord.xy);
    WORK_COUNT(kWorkFragments, 1);
    ivec2 texel = ivec2(gl_FragCoord.xy);
    vec3 w = fragmentRay(gl_FragCoord.xy);
    float d = texelFetch(uDistance, texel, 0).r;
    float x = min(length(vPosition), d);
    // Counter-clockwise seen from inside the volume: a front-facing fragment is where the ray leaves it.
    float s = gl_FrontFacing ? 1.0 : -1.0;
    // The term's span, [x, d] relative to the surface or [0, x] from the eye, chosen first so that the
    // segment integral is inlined once (llvmpipe runs every inlined copy for every fragment).
    bool fromSurface = uOriginAtSurface != 0;
    if (fromSurface) s = -s;
    float x0 = fromSurface ? x : 0.0;
    float x1 = fromSurface ? d : x;
    vec3 term = uConstant != 0 ? vec3(x1 - x0) : segmentAirlightOutsideBall(gLights[uLightIndex], w, x0, x1, uNearRadius);
    oTotal = vec4(s * term, gl_FrontFacing ? 1.0 : -1.0);
    oPositive = vec4(s > 0.0 ? term : vec3(0.0), 0.0);
    oNegative = vec4(s < 0.0 ? term : vec3(0.0), 0.0);
    // b: the crossing lies in front of the near plane (without the depth clamp it would be clipped and
    // its term lost); a: it lies beyond the surface (its distance clamped to d).
    oCrossings = vec4(1.0, gl_FrontFacing ? 1.0 : -1.0, dot(vPosition, uForward) < uNear ? 1.0 : 0.0,
                      length(vPosition) > d ? 1.0 : 0.0);
}
