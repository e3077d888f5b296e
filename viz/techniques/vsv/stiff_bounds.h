// What vsv and ivsv promise on the stiff-case suite (viz/report/stiff_suite.h) at their stiffSettings()
// (512 voxels per axis, combine=exact): about twice the worst relative L2 measured per case class at
// 33x25 (the table in README.md). ivsv shades every light but an area light with an inner vsv, and no
// stiff case has an area light, so both techniques declare the same bounds.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "debug/technique.h"

namespace viz::vsv {

inline std::optional<StiffBound> stiffBound(const std::string& caseClass) {
    static const std::map<std::string, StiffBound> kBounds = {
        {"medium", {0.005, "combine=exact integrates each lit run analytically: thick media cost nothing"}},
        {"intensity", {0.004, "linear in the intensity; float holds 1e-3 to 1e7 without clamping"}},
        {"scale", {0.005, "eye-relative angles and distance-valued shadow maps are scale-free"}},
        {"singular-ray", {0.025, "rays next to the light skip the grid and test the shadow map directly"}},
        {"near-light", {1e-4, "the ray past the light skips the grid; its lit runs are integrated analytically "
                               "with the ray's own distance from the light (7.3e-7)"}},
        {"epipole", {0.05, "epipole rays test the map directly; a sun's light lines (y = t sin alpha) are coarse "
                           "for rays almost along the baseline: the grazing sun is the worst"}},
        {"camera-placement", {0.01, "the grid covers what the camera sees wherever it stands"}},
        {"geometry", {0.05, "the grid resamples the shared shadow map: slivers it drops, vsv drops too"}},
        {"depth-range", {0.025, "the voxelizer applies the shared lookup's bias, so 500-unit texels do not "
                                "shadow their own receivers"}},
        {"leak", {0.15, "the voxelizer reads the shared medium lookup, but the grid places the grazing ceiling's "
                         "shadow by whole cells: light shows under it (0.0175 at the stiff settings' 512 cells)"}},
        {"phase", {0.045, "each lit run integrates the HG lobe analytically; g = 0.99 peaks near the solar "
                          "epipole, where the sun's light lines are coarsest"}},
    };
    return boundOf(kBounds, caseClass);
}

}  // namespace viz::vsv
