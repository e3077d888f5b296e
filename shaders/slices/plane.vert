#version 450 core
// slices/plane.vert: places sampling plane i of N (Mitchell 2004, "Positioning the Sampling Planes").
// No vertex buffer: vertex v of plane i is gl_VertexID = 6 i + v. The plane is the view-aligned quad at
// view depth s_i (along camera forward) spanning the view-space bounding box of the light's frustum,
// found by interpolating within that box. Plane 0 is the farthest (drawn first: back to front).
// Output: the plane's depth s_i (flat) and index; gl_ClipDistance[0..5] against the light frustum's six planes
// (from the light's shadow matrix: w +- x, w +- y, w +- z >= 0) with CLIP, then the two user planes with
// USER_CLIP; the host enables exactly the distances written.

uniform mat4 uViewProj;     // eye-relative world -> camera clip space
uniform vec3 uRight;        // camera basis, world axes
uniform vec3 uUp;
uniform vec3 uForward;
uniform vec2 uBoxMinXY;     // view-space box of the light frustum (x along uRight, y along uUp)
uniform vec2 uBoxMaxXY;
uniform float uDepthFar;    // view depth of plane 0's slab far edge
uniform float uSpacing;     // plane spacing in view depth, delta s
uniform float uDrawNear;    // planes nearer than this (just beyond znear) are drawn at it
uniform mat4 uLightMatrix;  // eye-relative world -> the light's clip space (shadow matrix)
uniform int uClipLight;     // 1: clip to the light frustum (spot lights, or directional_box=1)
uniform vec4 uUserPlane0;   // user clip planes, eye-relative world: dot(plane, (p, 1)) >= 0 is kept
uniform vec4 uUserPlane1;

flat out float vDepth;      // s_i, the plane's view depth
flat out int vPlane;

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
    float s = max(uDepthFar - (float(plane) + 0.5) * uSpacing, uDrawNear);
    vec2 xy = mix(uBoxMinXY, uBoxMaxXY, c);
    vec3 p = xy.x * uRight + xy.y * uUp + s * uForward;
    vDepth = s;
    vPlane = plane;
    gl_Position = uViewProj * vec4(p, 1.0);

#ifdef CLIP
    // uClipLight = 0 (a directional light, whose lit volume is unbounded): nothing is clipped. Writing
    // +1 rather than disabling the planes works around the llvmpipe behaviour noted above.
    vec4 lc = uClipLight != 0 ? uLightMatrix * vec4(p, 1.0) : vec4(0.0, 0.0, 0.0, 1.0);
    gl_ClipDistance[0] = lc.w + lc.x;
    gl_ClipDistance[1] = lc.w - lc.x;
    gl_ClipDistance[2] = lc.w + lc.y;
    gl_ClipDistance[3] = lc.w - lc.y;
    gl_ClipDistance[4] = lc.w + lc.z;
    gl_ClipDistance[5] = lc.w - lc.z;
#endif
#ifdef USER_CLIP
    gl_ClipDistance[kFirstUserPlane] = dot(uUserPlane0, vec4(p, 1.0));
    gl_ClipDistance[kFirstUserPlane + 1] = dot(uUserPlane1, vec4(p, 1.0));
#endif
}
