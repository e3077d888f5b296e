// The camera's rays in eye-relative world space: the float form of scene::pixelRay (viz/scene/camera.h),
// one definition for every technique that shades per pixel. The host sets the camera's frame.
#ifndef COMMON_CAMERA_RAY_GLSL
#define COMMON_CAMERA_RAY_GLSL

uniform ivec2 uSize;     // the image, pixels
uniform vec3 uForward;   // camera frame, unit vectors
uniform vec3 uRight;
uniform vec3 uUp;
uniform float uTanHalf;  // tan(yfov / 2)
uniform float uAspect;   // width / height of the view

// The ray through the centre of pixel `texel` in GL image coordinates (y = 0 the bottom row): pixel
// (x, H - 1 - y) of scene::pixelRay, whose rows count from the top. Techniques whose passes must agree on
// a pixel's ray to the bit (minmax's gamma ranges and traversal) call this same function.
vec3 pixelRay(ivec2 texel) {
    float yTop = float(uSize.y - 1 - texel.y);
    float ndcX = 2.0 * (float(texel.x) + 0.5) / float(uSize.x) - 1.0;
    float ndcY = 1.0 - 2.0 * (yTop + 0.5) / float(uSize.y);
    return normalize(uForward + (ndcX * uTanHalf * uAspect) * uRight + (ndcY * uTanHalf) * uUp);
}

// The ray through window position `fragCoord` (gl_FragCoord convention: pixel centres at .5, y = 0 at
// the bottom), for rasterised passes; at a pixel centre it is pixelRay's ray up to rounding.
vec3 fragmentRay(vec2 fragCoord) {
    float ndcX = 2.0 * fragCoord.x / float(uSize.x) - 1.0;
    float ndcY = 2.0 * fragCoord.y / float(uSize.y) - 1.0;
    return normalize(uForward + (ndcX * uTanHalf * uAspect) * uRight + (ndcY * uTanHalf) * uUp);
}

#endif  // COMMON_CAMERA_RAY_GLSL
