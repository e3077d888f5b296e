// The camera ray through a pixel's centre, eye-relative world space (scene::pixelRay in float): shared by
// minmax/traverse.comp and minmax/gamma_range.comp, which must agree on every pixel's ray to the bit (the
// row ranges of a point light are the largest gamma the traversal will ask for).
#ifndef MINMAX_CAMERA_RAY_GLSL
#define MINMAX_CAMERA_RAY_GLSL

uniform ivec2 uSize;
uniform vec3 uForward;
uniform vec3 uRight;
uniform vec3 uUp;
uniform float uTanHalf;
uniform float uAspect;

// texel: GL image coordinates (y = 0 the bottom row).
vec3 pixelRay(ivec2 texel) {
    float yTop = float(uSize.y - 1 - texel.y);
    float ndcX = 2.0 * (float(texel.x) + 0.5) / float(uSize.x) - 1.0;
    float ndcY = 1.0 - 2.0 * (yTop + 0.5) / float(uSize.y);
    return normalize(uForward + (ndcX * uTanHalf * uAspect) * uRight + (ndcY * uTanHalf) * uUp);
}

// A ray along the epipolar axis lies in every slice and has no gamma parametrisation.
bool onEpipolarAxis(vec3 w, vec3 axis) { return length(cross(w, axis)) < 1e-5; }

#endif  // MINMAX_CAMERA_RAY_GLSL
