// Area light -> virtual point lights (Halton points, or the centres of a grid of equal cells of the
// emitter), and the scene -> a point cloud for imperfect shadow maps, plus the paraboloid mapping of a
// VPL's hemisphere onto its shadow-map tile. Pure CPU, shared by ivsv and its tests; the paraboloid is
// mirrored in shaders/vsv/ism.glsl.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "scene/texture_sampling.h"

namespace viz::vsv {

// Radical inverse of i in the given prime base (the Halton sequence's coordinate).
inline double radicalInverse(std::uint32_t i, std::uint32_t base) {
    double inv = 1.0 / base, f = inv, r = 0.0;
    while (i > 0) {
        r += f * double(i % base);
        i /= base;
        f *= inv;
    }
    return r;
}

struct Vpl {
    glm::dvec3 position{0.0};  // world
    glm::dvec3 normal{0.0};    // the emitter's normal (emission side)
    glm::dvec3 weight{0.0};    // L_e * dA, dA = area / count: the VPL's radiant intensity along the normal
    glm::dvec2 uv{0.0};
    // The grid layout's cell (world): corner + [0,1]^2 of (edgeU, edgeV); zero edges for a Halton point,
    // which has no cell of its own.
    glm::dvec3 corner{0.0}, edgeU{0.0}, edgeV{0.0};
    glm::dvec2 uvSize{0.0};  // the cell's extent in uv (zero for a Halton point)
};

// count VPLs at Halton points (bases 2, 3; index from 1) of the emitter's uv square:
// p = centre + (2u - 1) halfU + (2v - 1) halfV (uv (0,0) at centre - halfU - halfV, as area_light.h).
inline std::vector<Vpl> sampleVpls(const scene::Scene& scene, const scene::Light& light, int count) {
    std::vector<Vpl> out;
    const double area = 4.0 * glm::length(glm::cross(light.halfU, light.halfV));
    const scene::Texture* tex =
        light.emissionTexture >= 0 ? &scene.textures[std::size_t(light.emissionTexture)] : nullptr;
    for (int i = 0; i < count; ++i) {
        Vpl v;
        v.uv = {radicalInverse(std::uint32_t(i + 1), 2), radicalInverse(std::uint32_t(i + 1), 3)};
        v.position = light.position + (2.0 * v.uv.x - 1.0) * light.halfU + (2.0 * v.uv.y - 1.0) * light.halfV;
        v.normal = glm::normalize(light.direction);
        glm::dvec3 le = light.radiance;
        if (tex) le *= glm::dvec3(scene::sampleLinearRgb(*tex, v.uv));
        v.weight = le * (area / count);
        out.push_back(v);
    }
    return out;
}

// The grid of `count` equal cells, nx x ny = count, whose cells are closest to square on an emitter of
// half-extents lengths |halfU|, |halfV| (a prime count gives one row).
inline glm::ivec2 vplGridSize(const scene::Light& light, int count) {
    const double aspect = glm::length(light.halfU) / std::max(glm::length(light.halfV), 1e-300);
    glm::ivec2 best{count, 1};
    double bestCost = 1e300;
    for (int nx = 1; nx <= count; ++nx) {
        if (count % nx) continue;
        const int ny = count / nx;
        const double cost = std::abs(std::log((aspect / nx) / (1.0 / ny)));  // log of the cell's aspect
        if (cost < bestCost - 1e-12) bestCost = cost, best = {nx, ny};
    }
    return best;
}

// count VPLs at the centres of the vplGridSize cells of the emitter, each carrying its cell and L_e's mean
// over it (the emission texture's exact mean, scene::averageLinearRgb), so that the VPLs' weights sum to
// the emitter's power per steradian along its normal exactly. VPL i is the free cell nearest (in uv) to
// the Halton point i + 1, so the VPLs come in about the order of the Halton layout, for which the
// interleaved gather's subsets ((i + i / 9) mod 9) were made. Measured on tv-room at 160x120, 256 VPLs,
// the interleaved gather against the full one: 0.039 in this order, 0.045 taking each cell at the first
// Halton point inside it, 0.055 with each subset a lattice of every third cell each way; 0.031 for Halton
// points themselves.
inline std::vector<Vpl> gridVpls(const scene::Scene& scene, const scene::Light& light, int count) {
    const glm::ivec2 n = vplGridSize(light, count);
    const double area = 4.0 * glm::length(glm::cross(light.halfU, light.halfV));
    const scene::Texture* tex =
        light.emissionTexture >= 0 ? &scene.textures[std::size_t(light.emissionTexture)] : nullptr;
    std::vector<bool> taken(std::size_t(count), false);
    std::vector<Vpl> out;
    for (int i = 0; i < count; ++i) {
        const glm::dvec2 h{radicalInverse(std::uint32_t(i + 1), 2), radicalInverse(std::uint32_t(i + 1), 3)};
        int pick = 0;
        double nearest = 1e300;
        for (int c = 0; c < count; ++c) {
            if (taken[std::size_t(c)]) continue;
            const glm::dvec2 centre{(c % n.x + 0.5) / n.x, (c / n.x + 0.5) / n.y};
            const double d2 = glm::dot(centre - h, centre - h);
            if (d2 < nearest) nearest = d2, pick = c;
        }
        taken[std::size_t(pick)] = true;
        const glm::dvec2 uv0{double(pick % n.x) / n.x, double(pick / n.x) / n.y};
        const glm::dvec2 uv1{double(pick % n.x + 1) / n.x, double(pick / n.x + 1) / n.y};
        Vpl v;
        v.uv = 0.5 * (uv0 + uv1);
        v.position = light.position + (2.0 * v.uv.x - 1.0) * light.halfU + (2.0 * v.uv.y - 1.0) * light.halfV;
        v.normal = glm::normalize(light.direction);
        v.corner = light.position + (2.0 * uv0.x - 1.0) * light.halfU + (2.0 * uv0.y - 1.0) * light.halfV;
        v.edgeU = (2.0 / n.x) * light.halfU;
        v.edgeV = (2.0 / n.y) * light.halfV;
        v.uvSize = uv1 - uv0;
        glm::dvec3 le = light.radiance;
        if (tex) le *= scene::averageLinearRgb(*tex, uv0, uv1);
        v.weight = le * (area / count);
        out.push_back(v);
    }
    return out;
}

// count points uniformly by area over every triangle except those of mesh `skipMesh` (the emitter:
// its own points would shadow its VPLs). Deterministic for a seed.
inline std::vector<glm::dvec3> samplePointCloud(const scene::Scene& scene, int count, int skipMesh,
                                                std::uint32_t seed = 1) {
    struct Tri {
        glm::dvec3 a, b, c;
    };
    std::vector<Tri> tris;
    std::vector<double> cumulative;
    double total = 0.0;
    for (int m = 0; m < int(scene.meshes.size()); ++m) {
        if (m == skipMesh) continue;
        const scene::Mesh& mesh = scene.meshes[std::size_t(m)];
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            Tri t{glm::dvec3(mesh.positions[mesh.indices[i]]), glm::dvec3(mesh.positions[mesh.indices[i + 1]]),
                  glm::dvec3(mesh.positions[mesh.indices[i + 2]])};
            total += 0.5 * glm::length(glm::cross(t.b - t.a, t.c - t.a));
            tris.push_back(t);
            cumulative.push_back(total);
        }
    }
    std::vector<glm::dvec3> points;
    if (tris.empty() || total <= 0.0) return points;
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    points.reserve(std::size_t(count));
    for (int i = 0; i < count; ++i) {
        const double pick = unit(rng) * total;
        const std::size_t t = std::size_t(std::lower_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin());
        const Tri& tri = tris[std::min(t, tris.size() - 1)];
        double s = unit(rng), r = unit(rng);
        if (s + r > 1.0) {
            s = 1.0 - s;
            r = 1.0 - r;
        }
        points.push_back(tri.a + s * (tri.b - tri.a) + r * (tri.c - tri.a));
    }
    return points;
}

// Tangent frame of a VPL's hemisphere (x, y; z = normal).
inline void hemisphereFrame(const glm::dvec3& n, glm::dvec3& x, glm::dvec3& y) {
    const glm::dvec3 a = std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    x = glm::normalize(glm::cross(a, n));
    y = glm::cross(n, x);
}

// Paraboloid map of the hemisphere around z: unit direction (x, y, z), z > 0 -> (x, y) / (1 + z) in the
// unit disk (Brabec et al. 2002, as imperfect shadow maps use it).
inline glm::dvec2 paraboloid(const glm::dvec3& local) { return glm::dvec2(local.x, local.y) / (1.0 + local.z); }

}  // namespace viz::vsv
