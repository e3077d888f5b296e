// slices.ray_planes: the picked pixel's record of every plane drawn (what the plane shader computed there
// and what the accumulation format kept), as a table for tests and export, and as a chart for the window.
#pragma once

#include "core/image.h"

namespace viz::slices {

// Status of a plane at the picked pixel; the codes of shaders/slices/pick_record.glsl.
enum class PickStatus {
    None = 0,           // no fragment and no clip test explains it (a polygon edge)
    Added = 1,          // shaded and blended into the accumulation
    BeyondSurface = 2,  // t > d: discarded, the ray ended at the surface
    LightFrustum = 3,   // clipped away by the light frustum
    UserPlane = 4,      // clipped away by a user plane
    OutsideQuad = 5,    // the plane's quad (the light volume's view-space box) misses the pixel
};

// Columns of the table (4 channels each); one row per plane drawn, draw set after draw set, back to front.
enum RayPlaneColumn {
    kColWhere = 0,  // plane i (0 = farthest), view depth s_i, t along the ray, dt = delta_s / dot(w, forward)
    kColTest,       // status (PickStatus), shadow test V (-1: not tested), mask channel (-1: all), surface d
    kColValue,      // the shader's output in stored units (before the blend quantises it)
    kColAdded,      // what the accumulation gained: after - before, as the format stored it
    kColAfter,      // the pixel's accumulation after this plane (stored units)
    kColSet,        // scene light (-1: the unbounded lights), draw set, L_air added, unquantised L_air (sum of rgb)
    kRayPlaneColumns
};

// The table as a picture (RGB, row 0 at the top): one column band per plane, nearest plane at the left
// (t grows to the right; draw sets side by side). Top: each plane's L_air as shaded (grey) and as stored
// (orange), scaled to the largest; under it a status strip and a shadow-test strip (see the note in
// slices.cpp, where the run publishes the chart).
Image rayPlanesChart(const Image& table);

}  // namespace viz::slices
