#version 450 core
// slices/pick_replay.frag: outputs plane j's recorded fragment value (what plane.frag wrote at the picked
// pixel) for the blend replay, and, once per plane (at its own record's texel), says why a plane that made no
// fragment there made none: the same tests as plane.vert's clip distances (light frustum: w +- x, y, z
// >= 0 in the light's clip space; user planes), evaluated at the pixel's sample point p = t w, and the
// plane's quad (the view-space box of the light volume). V = -1: no shadow test ran. Eye-relative world.
#include "slices/pick_record.glsl"

layout(binding = 0) uniform sampler2D uDistance;  // Euclidean d per pixel
layout(binding = 1) uniform sampler2D uReplay;    // this replay's target (the seed draw reads the row before)

uniform int uPickBase;     // this draw set's first record
uniform int uColumns;      // the replay target's width (record k at texel (k mod width, k / width))
uniform int uSeedRow;      // >= 0: the seed draw of that row; -1: records
uniform ivec2 uPickPixel;  // GL window coordinates
#include "slices/pixel_ray.glsl"  // uForward, uRight, uUp, uSize, uTanHalf, uAspect, pixelRay
#include "slices/slab.glsl"  // uSpacing, slabLength
uniform mat4 uLightMatrix;  // eye-relative world -> the light's clip space
uniform int uClipLight;     // 1: the planes were clipped to the light frustum
uniform int uUserClip;      // 1: and to the user planes
uniform vec4 uUserPlane0;
uniform vec4 uUserPlane1;
uniform vec2 uBoxMinXY;     // the planes' quad: view-space box (x along uRight, y along uUp)
uniform vec2 uBoxMaxXY;

flat in float vDepth;
flat in int vPlane;
flat in vec4 vValue;   // the plane's recorded output (0 when it made no fragment at the pixel)
flat in float vStatus;
layout(location = 0) out vec4 oColour;

void main() {
    if (uSeedRow >= 0) {
        // The accumulation at the end of the row before (written by earlier draws, behind a texture
        // barrier; this draw writes other texels only). Added to a cleared texel, stored exactly.
        oColour = texelFetch(uReplay, ivec2(uColumns - 1, uSeedRow - 1), 0);
        return;
    }
    int record = uPickBase + vPlane;
    oColour = vValue;
    ivec2 texel = ivec2(gl_FragCoord.xy);
    if (vStatus == kPickAdded || vStatus == kPickBeyondSurface || texel.y * uColumns + texel.x != record) return;
    // The pixel centre's ray, as plane.frag computes it.
    vec3 w = pixelRay(vec2(uPickPixel) + 0.5);
    float t = vDepth / dot(w, uForward);
    vec3 p = t * w;
    float status = kPickNone;
    vec2 xy = vec2(dot(p, uRight), dot(p, uUp));
    vec4 lc = uLightMatrix * vec4(p, 1.0);
    if (any(lessThan(xy, uBoxMinXY)) || any(greaterThan(xy, uBoxMaxXY)))
        status = kPickOutsideQuad;
    else if (uClipLight != 0 && any(lessThan(vec3(lc.w) - abs(lc.xyz), vec3(0.0))))
        status = kPickLightFrustum;
    else if (uUserClip != 0 && (dot(uUserPlane0, vec4(p, 1.0)) < 0.0 || dot(uUserPlane1, vec4(p, 1.0)) < 0.0))
        status = kPickUserPlane;
    gPick[record].where = vec4(float(vPlane), vDepth, t, slabLength(vPlane) / dot(w, uForward));
    gPick[record].test = vec4(status, -1.0, -1.0, texelFetch(uDistance, uPickPixel, 0).r);
    gPick[record].value = vec4(0.0);
}
