// A light's cell for the segment integral (airlight.glsl, pointSegmentCell): an area light's VPL with
// vpl_kernel=cell (lights.glsl, vplHasCell), along the eye ray w whose foot point of the light is at tP;
// AIRLIGHT_NO_CELL for every other light.
#ifndef VPL_CELL_GLSL
#define VPL_CELL_GLSL

#include "common/airlight.glsl"
#include "common/lights.glsl"

AirlightCell lightCellAlong(GpuLight L, vec3 w, float tP) {
    if (!vplHasCell(L)) return AIRLIGHT_NO_CELL;
    return airlightCellOf(L.spot.xyz, L.frameX.xyz, L.frameY.xyz, L.direction.xyz, L.spot.w, w, tP);
}

#endif  // VPL_CELL_GLSL
