// The unit ray through a pixel's centre from the eye (eye-relative world), as scene::pixelRay forms it:
// GL row 0 is the bottom, so ndc.y = 2 (y + 1/2) / H - 1. One copy for plane.frag (each plane's sample
// point), depth.frag (the first surface's depth) and pick_replay.frag (the picked pixel's records).
#ifndef SLICES_PIXEL_RAY_GLSL
#define SLICES_PIXEL_RAY_GLSL

uniform vec3 uForward;  // camera basis, world axes
uniform vec3 uRight;
uniform vec3 uUp;
uniform vec2 uSize;     // image size in pixels
uniform float uTanHalf; // tan(yfov / 2)
uniform float uAspect;

// centre: the pixel's centre in GL window coordinates (gl_FragCoord.xy, or a pixel + 0.5).
vec3 pixelRay(vec2 centre) {
    vec2 ndc = 2.0 * centre / uSize - 1.0;
    return normalize(uForward + (ndc.x * uTanHalf * uAspect) * uRight + (ndc.y * uTanHalf) * uUp);
}

#endif  // SLICES_PIXEL_RAY_GLSL
