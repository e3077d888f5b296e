#version 450 core
// slices/pick_replay.vert: replays the picked pixel's additive blend (slices.ray_planes). The records, in
// drawing order (draw set after draw set, each back to front), are laid out row by row over a target in
// the accumulation's format, uColumns to a row: record k at texel (k mod uColumns, k / uColumns). Record
// k's plane is a quad over the texels from k to the end of its row, so, drawn in order with the frame's
// blend (GL blends in primitive order), texel k ends up holding the pixel's accumulation after the
// records of its row up to k. Each row first gets the accumulation at the end of the row before it (the
// seed draw: uSeedRow >= 0), so texel k holds the accumulation after records 0..k, quantised as the
// frame's was. Rows keep the work at uColumns / 2 fragments a record. Plane 0 of a draw set is its
// farthest (as in plane.vert). No vertex buffer: vertex v of plane j is gl_VertexID = 6 j + v.
#include "slices/pick_record.glsl"

uniform int uPickBase;   // this draw set's first record
uniform int uRows;
uniform int uColumns;
uniform int uSeedRow;    // >= 0: the seed draw of that row (one quad over it); -1: records
uniform float uDepthFar; // as plane.vert: s_j = max(far - (j + 1/2) delta s, drawNear)
uniform float uSpacing;
uniform float uDrawNear;

flat out float vDepth;
flat out int vPlane;
flat out vec4 vValue;    // what the plane added at the picked pixel (0: no fragment there)
flat out float vStatus;

const vec2 kCorners[6] = vec2[6](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));

void main() {
    vec2 c = kCorners[gl_VertexID % 6];
    int plane = gl_VertexID / 6;
    int k = uPickBase + plane;
    int row = uSeedRow >= 0 ? uSeedRow : k / uColumns;
    float x0 = uSeedRow >= 0 ? 0.0 : float(k % uColumns);
    vec2 p = mix(vec2(x0, float(row)), vec2(float(uColumns), float(row + 1)), c) / vec2(float(uColumns), float(uRows));
    gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0);
    vDepth = max(uDepthFar - (float(plane) + 0.5) * uSpacing, uDrawNear);
    vPlane = plane;
    vStatus = kPickNone;
    vValue = vec4(0.0);
    if (uSeedRow >= 0) return;
    // Read once per vertex rather than per fragment.
    vStatus = gPick[k].test.x;
    vValue = vStatus == kPickAdded ? gPick[k].value : vec4(0.0);
}
