// The "VPL cells" view of the shared passes: an area light's emitter as its VPLs see it (render/gpu_lights.cpp),
// each cell filled with its VPL's colour, the cells' edges, and the nodes where its shadow cube sits.
#pragma once

#include <string>
#include <vector>

#include "debug/intermediate.h"
#include "render/gpu_lights.h"
#include "scene/scene.h"

namespace viz::render {

// One picture per area light of the scene (ids prefix.vpl_cells, prefix.vpl_cells.1, ...): the emitter's
// uv square (u right, v down) at its aspect ratio, each cell its VPL's L_e (the emission texture's mean
// over the cell) over the brightest cell's largest channel; grey lines: the cells' edges (the
// Gauss-Legendre weights: narrow at the rim); white dots ringed in black: the nodes. None without an
// area light.
std::vector<Intermediate> vplCellsViews(const scene::Scene& scene, const GpuLights& lights, const std::string& prefix);

}  // namespace viz::render
