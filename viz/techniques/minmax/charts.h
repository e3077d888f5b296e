// The CPU-drawn intermediates of minmax (plain images, no GL): the rectified map with the picked row, the
// picked row's min-max pyramid, the picked ray against its heightfield (Figure 4 of Chen et al. 2011),
// and the plots of the low-rank factorisation.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "core/image.h"
#include "debug/technique.h"
#include "techniques/minmax/low_rank.h"

namespace viz::minmax {

// An Intermediate holding a CPU image.

// S / pi as grey, row 0 at the top, the picked row in red; at most 1024 x 1024 (nearest rows and columns).
// readRows(sources) returns those rows of S one after another (columns floats each): the at most 1024 the
// picture shows, the picked one among them, in increasing order.
Image rectifiedView(const std::function<std::vector<float>(const std::vector<int>&)>& readRows, int columns,
                    int rows, int pickedRow);

// The widest chart of a row's columns, in pixels; a wider row's pixels each stand for several columns.
inline constexpr int kChartWidth = 1024;

// The 2n nodes of one row as a pyramid: level 0 (root) at the top, one band per level (min over max, beta /
// pi as grey); levels above the last `levelsBuilt` passes (plus the leaves) in blue. At most kChartWidth
// wide (a pixel over several nodes of a level shows their min and max), and its bands tall enough for
// about a 3:1 image (pyramidBandRows), so that a 2048-column row is not a strip a few pixels high.
Image pyramidView(const std::vector<glm::vec2>& tree, int levelsBuilt);
// Rows per band of the pyramid `width` pixels wide with `levels` levels: even, at least 4.
int pyramidBandRows(int width, int levels);

// The ray at height beta ending at column cEnd against the row's heightfield (grey where beta < S), and
// below one band per level with the nodes of the walk (minmax_tree.h traverse), the first `steps` (0: all):
// green lit, red shadowed, grey mixed. One pixel per column; the plot and the bands taller for a longer row.
Image traceView(const std::vector<glm::vec2>& tree, float beta, float cEnd, int steps);
// The nodes that walk visits in all (what traceView draws with steps = 0; steps >= it draws them all).
int walkLength(const std::vector<glm::vec2>& tree, float beta, float cEnd);

// Singular values as log10 bars over 12 decades (kept ones green), and B_i / Gamma_i as curves.
Image singularValuesView(const LowRank& lr);
// Where the rank-N factorisation errs: |I - I_N| / max |I| on each cell of the 64 x 64 grid of I sin(beta),
// x = gamma_j (gammaLo at the left), y = beta_k (betaLo at the top); all 0 when I is 0 everywhere.
Image reconstructionErrorView(const LowRank& lr);
Image basisView(const LowRank& lr);
// The same as plots with axes: sigma_i against i (log scale; kept and dropped ones as two curves), and
// B_i over beta (degrees) and Gamma_i over gamma (degrees; for a directional light gamma is the light
// ray's distance rho from the axis, in scene units), one curve per kept rank.
PlotData singularValuesPlot(const LowRank& lr);
std::vector<PlotData> basisPlots(const LowRank& lr, bool directional);

}  // namespace viz::minmax
