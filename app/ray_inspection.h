// The technique's own view of one camera ray, for the window's ray inspector: the value at the inspected
// pixel of every intermediate that has one texel per pixel (crossing counts, visited tree nodes, lit
// fraction, visibility, epipolar coordinates, ...), and the picked-pixel parameters that make the
// per-ray intermediates (minmax's walk, vsv's voxel column, ivsv's per-VPL terms) follow that pixel.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "debug/technique.h"
#include "plot/plot.h"

namespace airlight {

struct PixelReading {
    std::string id, label, units;
    int channels = 0;
    glm::vec4 value{0.0f};
};

// Values at `pixel` (x right, y down from the top row) of every intermediate in `out` whose size is the
// frame's: CPU images and 2D float / normalised GL textures (rows bottom-up, as GL renders them). Other
// intermediates (integer grids, meshes, maps in light space) are not per pixel and are left out.
std::vector<PixelReading> readingsAtPixel(const viz::FrameOutput& out, glm::ivec2 frame, glm::ivec2 pixel);

// The technique's own samples along the picked ray as series for the inspector's plot (x = t along the
// ray, y = integrand per unit length, sum of RGB, the axes of the reference's curve). slices.ray_planes:
// one point per plane that was shaded, its L_air divided by its dt, as the shader computed it ("slices,
// shaded") and as the accumulation format kept it ("slices, stored"). Empty when `out` has no such view.
std::vector<viz::plot::Series> rayViewSeries(const viz::FrameOutput& out);

// All of the above for one pixel of one run. The window reads it once per run and pixel (each reading
// is a GL readback), not once per frame.
struct PixelInspection {
    std::vector<PixelReading> readings;
    std::vector<std::string> rayViews;
    std::vector<viz::plot::Series> series;
};
PixelInspection inspectRun(const viz::Technique& technique, const viz::FrameOutput& out, glm::ivec2 frame,
                           glm::ivec2 pixel);

// Sets the technique's `pick_x` / `pick_y` to `pixel`; returns true when the technique has them and a
// value changed (the technique must run again for its per-ray intermediates).
bool pickPixel(const viz::Technique& technique, viz::Settings& settings, glm::ivec2 pixel);

// The ids of the intermediates in `out` that show the picked pixel's ray (Intermediate::rayView: a walk, a
// voxel column, per-VPL terms, the planes along it) of a technique with pick_x / pick_y. The inspector
// names them so the user can open them in a view.
std::vector<std::string> pickedRayViews(const viz::Technique& technique, const viz::FrameOutput& out);

}  // namespace airlight
