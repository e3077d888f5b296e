// The depth the planes are tested with (depth_test=1), one definition for both sides of the test: plane.vert
// gives each plane the depth where the part of the ray it adds begins, and depth.frag gives each pixel the
// depth of its first surface computed from the distance texture, the d plane.frag tests against. Both are
// the same function of a view depth, so the hardware test agrees with the shader's own however the
// rasteriser rounded the scene's depth (a ground quad 1e6 across rasterised its depth up to 6 % off).
#ifndef SLICES_PLANE_DEPTH_GLSL
#define SLICES_PLANE_DEPTH_GLSL

uniform vec2 uDepthFromView;  // the camera's clip z at view depth s is x s + y (its w is s)

// A plane's depth is moved nearer by this (NDC, 2^-16) against the rounding of the two computations.
const float kPlaneDepthMargin = 1.0 / 65536.0;

// NDC depth at view depth s, inside [-1, 1] (nearer than znear: -1; beyond the far plane: 1).
float ndcDepthAtView(float s) {
    return clamp((uDepthFromView.x * s + uDepthFromView.y) / max(s, 1.0e-30), -1.0, 1.0);
}

#endif  // SLICES_PLANE_DEPTH_GLSL
