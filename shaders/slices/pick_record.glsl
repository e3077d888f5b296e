// slices/pick_record.glsl: the picked pixel's record of one sampling plane (slices.ray_planes), one per
// plane and draw set. plane.frag writes the planes that made a fragment at the pixel; pick_replay.frag
// says why the others made none. The status codes are mirrored by PickStatus in viz/techniques/slices/ray_planes.h.
#include "common/host_device.glsl"

struct PickRecord {
    vec4 where;  // plane i (0 = farthest), view depth s_i, t = s_i / dot(w, forward), dt = delta_s / dot(w, forward)
    vec4 test;   // status (kPick*), shadow test V, channel (rgba8-mask: i mod 4; else -1), surface distance d
    vec4 value;  // the fragment's output in stored units: what the blend adds before it quantises
};
layout(std430, binding = kFirstFreeSsboBinding) buffer PickRecords { PickRecord gPick[]; };

const float kPickNone = 0.0;           // no fragment, and no clip test explains it (a polygon edge)
const float kPickAdded = 1.0;          // shaded and blended into the accumulation
const float kPickBeyondSurface = 2.0;  // t > d: discarded (the ray ended at the surface)
const float kPickLightFrustum = 3.0;   // clipped away by the light frustum (gl_ClipDistance 0..5)
const float kPickUserPlane = 4.0;      // clipped away by a user plane (y >= clip_y_min, y <= clip_y_max)
const float kPickOutsideQuad = 5.0;    // the plane's quad (the light volume's view-space box) misses the pixel
