#version 450 core
// slices/plane.vert: places sampling plane i of N (Mitchell 2004, "Positioning the Sampling Planes").
// No vertex buffer: vertex v of plane i is gl_VertexID = 6 i + v. The plane is the view-aligned quad at
// view depth s_i (along camera forward) spanning the view-space bounding box of the light's frustum,
// found by interpolating within that box. Plane 0 is the farthest (drawn first: back to front).
// Output: the plane's depth s_i (flat) and index; gl_ClipDistance[0..5] against the light frustum's six planes
// (from the light's shadow matrix: w +- x, w +- y, w +- z >= 0) with CLIP, then the two user planes with
// USER_CLIP; the host enables exactly the distances written.
// Depth: every plane is drawn at the depth where the part of the ray it adds begins (its slab's start, or
// the plane itself with one sample), moved nearer by a margin (slices/plane_depth.glsl); with depth_test=1
// the host tests it against a depth buffer made from the first surface's distance (slices/depth.frag:
// Mitchell draws the planes "after the rest of the scene"), so a fragment is rejected unshaded where
// plane.frag would drop it as beyond the first surface, and the image does not change. The depth is kept
// inside [-w, w]: no plane is clipped by the camera's near or far plane for it.
// SLAB_EQUIANGULAR (plane.frag integrates the plane's whole slab): the quad and the light-frustum clip
// planes are widened to every pixel whose ray meets the light volume somewhere in the slab, not only at
// the plane. On the plane at view depth s, the point p stands for the ray's points f p, f in [s_lo / s,
// s_hi / s]; the quad spans the box scaled by s / s_lo and s / s_hi, and a frustum plane
// dot(n, p) + c >= 0 keeps p when f dot(n, p) + c >= 0 at either end, which is f_lo dot(n, p) + c >= 0 for
// c >= 0 (the plane keeps the eye) and f_hi dot(n, p) + c >= 0 otherwise: still linear in p. So it
// keeps a superset; plane.frag cuts each ray to the exact part.

uniform mat4 uViewProj;     // eye-relative world -> camera clip space
uniform vec3 uRight;        // camera basis, world axes
uniform vec3 uUp;
uniform vec3 uForward;
uniform float uTanHalf;     // tan(yfov / 2)
uniform float uAspect;
uniform vec2 uBoxMinXY;     // view-space box of the light frustum (x along uRight, y along uUp)
uniform vec2 uBoxMaxXY;
uniform float uDepthFar;    // view depth of plane 0's slab far edge
uniform float uSpacing;     // plane spacing in view depth, delta s
uniform float uDrawNear;    // planes nearer than this (just beyond znear) are drawn at it
uniform mat4 uLightMatrix;  // eye-relative world -> the light's clip space (shadow matrix)
uniform int uClipLight;     // 1: clip to the light frustum (spot lights, or directional_box=1)
uniform vec4 uUserPlane0;   // user clip planes, eye-relative world: dot(plane, (p, 1)) >= 0 is kept
uniform vec4 uUserPlane1;
#include "slices/plane_depth.glsl"

flat out float vDepth;      // s_i, the plane's view depth
flat out int vPlane;
#ifdef SLAB_EQUIANGULAR
flat out vec2 vSlab;        // the slab's view-depth range [s_lo, s_hi], s_lo >= 0 (the eye)
#endif

// Only the distances in use are declared and written: Mesa llvmpipe was seen to clip with written
// distances whose GL_CLIP_DISTANCEi was disabled.
#if defined(CLIP) && defined(USER_CLIP)
const int kFirstUserPlane = 6;
out float gl_ClipDistance[8];
#elif defined(CLIP)
out float gl_ClipDistance[6];
#elif defined(USER_CLIP)
const int kFirstUserPlane = 0;
out float gl_ClipDistance[2];
#endif

const vec2 kCorners[6] = vec2[6](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));

void main() {
    int plane = gl_VertexID / 6;
    vec2 c = kCorners[gl_VertexID % 6];
    // Midpoint of slab i: s_i = far - (i + 1/2) delta s.
    // The nearest slab may start at the eye; its plane is drawn where the camera does not clip it.
    float sMid = uDepthFar - (float(plane) + 0.5) * uSpacing;
    float s = max(sMid, uDrawNear);
#ifdef SLAB_EQUIANGULAR
    float sLo = max(sMid - 0.5 * uSpacing, 0.0), sHi = sMid + 0.5 * uSpacing;
    vSlab = vec2(sLo, sHi);
    // Cut to the view at depth s (1 % wider): a slab reaching the eye scales the box without bound, and
    // llvmpipe drops a quad a thousand times the screen's size.
    float scaleLo = s / max(sLo, 1.0e-3 * s), scaleHi = s / sHi;
    vec2 view = 1.01 * s * vec2(uTanHalf * uAspect, uTanHalf);
    vec2 lo = clamp(min(uBoxMinXY * scaleLo, uBoxMinXY * scaleHi), -view, view);
    vec2 hi = clamp(max(uBoxMaxXY * scaleLo, uBoxMaxXY * scaleHi), -view, view);
    vec2 xy = mix(lo, hi, c);
#else
    vec2 xy = mix(uBoxMinXY, uBoxMaxXY, c);
#endif
    vec3 p = xy.x * uRight + xy.y * uUp + s * uForward;
    vDepth = s;
    vPlane = plane;
    gl_Position = uViewProj * vec4(p, 1.0);
#ifdef SLAB_EQUIANGULAR
    float sTest = sLo;
#else
    float sTest = s;
#endif
    gl_Position.z = max(ndcDepthAtView(sTest) - kPlaneDepthMargin, -1.0) * gl_Position.w;

#ifdef CLIP
    // uClipLight = 0 (a directional light, whose lit volume is unbounded): nothing is clipped. Writing
    // +1 rather than disabling the planes works around the llvmpipe behaviour noted above.
    vec4 lc = uClipLight != 0 ? uLightMatrix * vec4(p, 1.0) : vec4(0.0, 0.0, 0.0, 1.0);
#ifdef SLAB_EQUIANGULAR
    // c of each plane is its distance at the eye (p = 0): the matrix's last column.
    vec4 le = uClipLight != 0 ? uLightMatrix[3] : vec4(0.0, 0.0, 0.0, 1.0);
    float fLo = sLo / s, fHi = sHi / s;
    float atP[6] = float[6](lc.w + lc.x, lc.w - lc.x, lc.w + lc.y, lc.w - lc.y, lc.w + lc.z, lc.w - lc.z);
    float atEye[6] = float[6](le.w + le.x, le.w - le.x, le.w + le.y, le.w - le.y, le.w + le.z, le.w - le.z);
    for (int j = 0; j < 6; ++j) gl_ClipDistance[j] = (atEye[j] >= 0.0 ? fLo : fHi) * (atP[j] - atEye[j]) + atEye[j];
#else
    gl_ClipDistance[0] = lc.w + lc.x;
    gl_ClipDistance[1] = lc.w - lc.x;
    gl_ClipDistance[2] = lc.w + lc.y;
    gl_ClipDistance[3] = lc.w - lc.y;
    gl_ClipDistance[4] = lc.w + lc.z;
    gl_ClipDistance[5] = lc.w - lc.z;
#endif
#endif
#ifdef USER_CLIP
    gl_ClipDistance[kFirstUserPlane] = dot(uUserPlane0, vec4(p, 1.0));
    gl_ClipDistance[kFirstUserPlane + 1] = dot(uUserPlane1, vec4(p, 1.0));
#endif
}
