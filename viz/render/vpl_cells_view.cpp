#include "render/vpl_cells_view.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "render/host_device.h"

namespace viz::render {

namespace {

constexpr int kLongSide = 192;  // pixels along the emitter's longer edge

struct CellInUv {
    glm::dvec2 lo, hi, node;
    glm::dvec3 colour;  // L_e, the VPL's radiant / dA
};

}  // namespace

std::vector<Intermediate> vplCellsViews(const scene::Scene& scene, const GpuLights& lights, const std::string& prefix) {
    std::vector<Intermediate> out;
    const glm::dvec3 eye = lights.eye();
    for (std::size_t li = 0; li < scene.lights.size(); ++li) {
        const scene::Light& light = scene.lights[li];
        if (light.type != scene::LightType::Area) continue;
        // uv of an eye-relative point on the emitter: (0, 0) at position - halfU - halfV.
        const glm::dvec3 origin = light.position - light.halfU - light.halfV - eye;
        const double uu = 4.0 * glm::dot(light.halfU, light.halfU), vv = 4.0 * glm::dot(light.halfV, light.halfV);
        if (!(uu > 0.0) || !(vv > 0.0)) continue;
        const auto uvOf = [&](glm::dvec3 p) {
            return glm::dvec2(glm::dot(p - origin, 2.0 * light.halfU) / uu, glm::dot(p - origin, 2.0 * light.halfV) / vv);
        };
        std::vector<CellInUv> cells;
        double peak = 0.0;
        for (const GpuLightCpu& L : lights.lights()) {
            if (L.info.x != hd::kLightVpl || L.info.w != int(li)) continue;
            const glm::dvec3 corner(L.spot);
            CellInUv c;
            const glm::dvec2 a = uvOf(corner), b = uvOf(corner + glm::dvec3(L.frameX) + glm::dvec3(L.frameY));
            c.lo = glm::min(a, b);
            c.hi = glm::max(a, b);
            c.node = uvOf(glm::dvec3(L.position));
            c.colour = glm::dvec3(L.radiant) / std::max(double(L.spot.w), 1e-300);
            peak = std::max({peak, c.colour.r, c.colour.g, c.colour.b});
            cells.push_back(c);
        }
        if (cells.empty()) continue;
        const double aspect = std::sqrt(uu / vv);
        const int w = aspect >= 1.0 ? kLongSide : std::max(8, int(std::lround(kLongSide * aspect)));
        const int h = aspect >= 1.0 ? std::max(8, int(std::lround(kLongSide / aspect))) : kLongSide;
        auto image = std::make_shared<Image>(w, h, 3);
        for (const CellInUv& c : cells) {
            const int x0 = int(std::lround(c.lo.x * w)), x1 = int(std::lround(c.hi.x * w));
            const int y0 = int(std::lround(c.lo.y * h)), y1 = int(std::lround(c.hi.y * h));
            for (int y = std::max(0, y0); y < std::min(h, y1); ++y)
                for (int x = std::max(0, x0); x < std::min(w, x1); ++x) {
                    const bool edge = x == x0 || y == y0;
                    for (int k = 0; k < 3; ++k)
                        image->at(x, y, k) = edge ? 0.35f : float(peak > 0.0 ? c.colour[k] / peak : 1.0);
                }
        }
        for (const CellInUv& c : cells) {
            const int cx = std::clamp(int(c.node.x * w), 0, w - 1), cy = std::clamp(int(c.node.y * h), 0, h - 1);
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const int x = cx + dx, y = cy + dy;
                    if (x < 0 || y < 0 || x >= w || y >= h) continue;
                    const bool ring = std::abs(dx) == 2 || std::abs(dy) == 2;
                    for (int k = 0; k < 3; ++k) image->at(x, y, k) = ring ? 0.0f : 1.0f;
                }
        }
        const std::string id = prefix + ".vpl_cells" + (out.empty() ? std::string() : "." + std::to_string(out.size()));
        out.push_back(cpuIntermediate(
            id, "VPL cells",
            "area light '" + light.name + "' in its uv square (u right, v down): each cell its VPL's L_e (the " +
                "emission's mean over the cell) over the brightest channel of all; grey lines: cell edges (equal " +
                "cells); white dots: the nodes, where each VPL's shadow cube sits",
            ViewKind::Colour, image));
        out.back().picture = true;
    }
    return out;
}

}  // namespace viz::render
