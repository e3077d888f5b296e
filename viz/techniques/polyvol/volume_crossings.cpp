#include "techniques/polyvol/volume_crossings.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "core/error.h"
#include "render/shadow_map_markers.h"
#include "render/shadow_maps.h"
#include "techniques/polyvol/light_volume_mesh.h"

namespace viz::polyvol {

namespace {

// Vertex positions of one light's volume, in float as volume_grid.glsl computes them.
class VolumeVertices {
public:
    // faces: the map's stored values per face (a 2D map: face 0 only).
    VolumeVertices(const VolumeGrid& grid, const render::GpuLightCpu& light,
                   const std::array<const std::vector<float>*, 6>& faces)
        : mGrid(grid), mLight(light), mFaces(faces), mN(grid.mapSize) {}

    glm::dvec3 key(std::uint32_t k) {
        const auto it = mCache.find(k);
        if (it != mCache.end()) return it->second;
        const glm::dvec3 p(keyPosition(k));
        mCache.emplace(k, p);
        return p;
    }

private:
    bool directional() const { return mGrid.mode == kModeDirectional; }
    glm::vec3 lightPos() const { return glm::vec3(mLight.position); }
    glm::vec3 lightDir() const { return glm::vec3(mLight.direction); }

    glm::vec2 texelNdc(int i, int j) const {
        return (glm::vec2(glm::min(glm::ivec2(i, j), glm::ivec2(mN - 1))) + 0.5f) * (2.0f / float(mN)) - 1.0f;
    }

    glm::vec3 directionalPoint(int i, int j, float depth) const {
        glm::vec2 ndc = texelNdc(i, j);
        const bool border = i == 0 || j == 0 || i >= mN - 1 || j >= mN - 1;
        if (border) ndc *= mGrid.skirt;
        const glm::vec3 q = mGrid.planeOrigin + ndc.x * mGrid.planeX + ndc.y * mGrid.planeY;
        return q + lightDir() * (depth - glm::dot(q, lightDir()));
    }

    glm::vec3 gridPosition(int face, int i, int j) const {
        const int ci = std::min(i, mN - 1), cj = std::min(j, mN - 1);
        const float stored = (*mFaces[std::size_t(face)])[std::size_t(cj) * std::size_t(mN) + std::size_t(ci)];
        const bool empty = stored >= 1.0e29f;  // cleared texel: nothing in front of the far plane
        if (directional()) return directionalPoint(i, j, empty ? mGrid.noHit : stored);
        const glm::vec2 ndc = texelNdc(i, j);
        if (mGrid.mode == kModeCube) {
            // The face's basis (shadow_map.glsl cubeFaceBasis): dir = forward + ndc.x right + ndc.y trueUp.
            glm::dvec3 f, u;
            render::ShadowMaps::cubeFaceBasis(face, f, u);
            const glm::vec3 forward(f), up(u);
            const glm::vec3 right = glm::cross(forward, up);
            const glm::vec3 trueUp = glm::cross(right, forward);
            const glm::vec3 dir = glm::normalize(forward + ndc.x * right + ndc.y * trueUp);
            return lightPos() + dir * (empty ? mGrid.noHit : stored);
        }
        const glm::vec3 dir = glm::normalize(mGrid.planeOrigin + ndc.x * mGrid.planeX + ndc.y * mGrid.planeY);
        // Outside the cone (A_spot = 0) the vertex is at the light (lights.glsl spotAttenuation).
        const float a = std::clamp(glm::dot(lightDir(), dir) * mLight.spot.x + mLight.spot.y, 0.0f, 1.0f);
        if (a * a == 0.0f) return lightPos();
        return lightPos() + dir * (empty ? mGrid.noHit : stored);
    }

    glm::vec3 keyPosition(std::uint32_t k) const {
        if (k == kApexKey) {
            if (!directional()) return lightPos();
            return mGrid.planeOrigin + lightDir() * (mGrid.capDepth - glm::dot(mGrid.planeOrigin, lightDir()));
        }
        const std::uint32_t stride = std::uint32_t(mGrid.keyStride);
        const std::uint32_t n2 = stride * stride;
        const int face = int(k / n2);
        const std::uint32_t rest = k % n2;
        const int i = int(rest % stride), j = int(rest / stride);
        if (face == 6) return directional() ? directionalPoint(i, j, mGrid.capDepth) : lightPos();
        return gridPosition(face, i, j);
    }

    const VolumeGrid& mGrid;
    const render::GpuLightCpu& mLight;
    std::array<const std::vector<float>*, 6> mFaces;
    int mN;
    std::unordered_map<std::uint32_t, glm::dvec3> mCache;
};

// Moller-Trumbore for the ray t w from the origin; t > 0. Zero-area triangles (the spot's caps) miss.
bool intersect(const glm::dvec3& w, const glm::dvec3& v0, const glm::dvec3& v1, const glm::dvec3& v2, double& t) {
    const glm::dvec3 e1 = v1 - v0, e2 = v2 - v0;
    const glm::dvec3 p = glm::cross(w, e2);
    const double det = glm::dot(e1, p);
    const double scale = glm::length(e1) * glm::length(e2);
    if (!(std::abs(det) > 1e-14 * scale)) return false;
    const glm::dvec3 s = -v0;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return false;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(w, q) / det;
    if (v < 0.0 || u + v > 1.0) return false;
    t = glm::dot(e2, q) / det;
    return t > 0.0;
}

// Texel-centre cells (i, j) = the quad of centres (i..i+1, j..j+1) that the ray's projection into the map
// passes through, with their neighbours (a crossing on a shared edge or a sloped face reaching over).
void cellsAlongRay(const glm::dmat4& m, const glm::dvec3& w, int n, double tMax, std::vector<char>& cells) {
    const glm::dvec4 c0 = m[3], c1 = m * glm::dvec4(w, 0.0);
    // Where the projection is defined (w > 0): the part of the ray in front of the light's plane.
    double lo = 0.0, hi = tMax;
    const double wEps = 1e-9 * (std::abs(c0.w) + std::abs(c1.w) * tMax + 1.0);
    if (c1.w == 0.0) {
        if (c0.w <= wEps) return;
    } else {
        const double r = (wEps - c0.w) / c1.w;
        if (c1.w > 0.0) lo = std::max(lo, r);
        else hi = std::min(hi, r);
    }
    if (!(lo < hi)) return;
    // Texel-centre coordinates f = (ndc / 2 + 1 / 2) n - 1/2: cell boundaries at integer f.
    const auto centreCoord = [&](double t, int axis) {
        const glm::dvec4 q = c0 + t * c1;
        return (q[axis] / q.w * 0.5 + 0.5) * double(n) - 0.5;
    };
    std::vector<double> cuts = {lo, hi};
    for (int axis = 0; axis < 2; ++axis) {
        const double a = std::clamp(centreCoord(lo, axis), -2.0, double(n) + 1.0);
        const double b = std::clamp(centreCoord(hi, axis), -2.0, double(n) + 1.0);
        for (int k = int(std::floor(std::min(a, b))) + 1; k <= int(std::ceil(std::max(a, b))) - 1; ++k) {
            const double x = (double(k) + 0.5) * 2.0 / double(n) - 1.0;
            const double denom = c1[axis] - x * c1.w;
            if (denom == 0.0) continue;
            const double t = (x * c0.w - c0[axis]) / denom;
            if (t > lo && t < hi) cuts.push_back(t);
        }
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
        const double mid = 0.5 * (cuts[k] + cuts[k + 1]);
        const double fx = centreCoord(mid, 0), fy = centreCoord(mid, 1);
        if (fx < -2.0 || fy < -2.0 || fx > double(n) + 1.0 || fy > double(n) + 1.0) continue;
        const int ci = int(std::floor(fx)), cj = int(std::floor(fy));
        for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di) {
                const int i = ci + di, j = cj + dj;
                if (i >= 0 && j >= 0 && i <= n - 2 && j <= n - 2) cells[std::size_t(j) * std::size_t(n) + std::size_t(i)] = 1;
            }
    }
}

// One triangle (keys counter-clockwise seen from the light) against the ray t w.
void testTriangle(VolumeVertices& vertices, const glm::dvec3& w, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                  std::vector<VolumeCrossing>& out) {
    const glm::dvec3 v0 = vertices.key(a), v1 = vertices.key(b), v2 = vertices.key(c);
    double t = 0.0;
    if (!intersect(w, v0, v1, v2, t)) return;
    // Front-facing from the eye (the origin): the eye is on the side the CCW normal points to, i.e.
    // inside the triangle's half-space of the lit volume, so the ray leaves it there (+1).
    const glm::dvec3 normal = glm::cross(v1 - v0, v2 - v0);
    out.push_back({t, glm::dot(normal, v0) < 0.0 ? +1 : -1});
}

// The adaptive triangles of face `face` (keys with `stride` = N + 1 texels per row, face f's from
// f stride^2) that can meet the ray: those whose cell range (in texels, the virtual column and row N
// clamped onto N - 1) meets a marked cell, found with a summed-area table of `cells`.
void testAdaptiveFace(VolumeVertices& vertices, const glm::dvec3& w, const std::vector<char>& cells, int n, int face,
                      std::uint32_t stride, const std::vector<std::uint32_t>& keys, std::vector<VolumeCrossing>& out) {
    const std::size_t m = std::size_t(n);
    std::vector<std::int32_t> sat((m + 1) * (m + 1), 0);
    for (std::size_t j = 0; j < m; ++j)
        for (std::size_t i = 0; i < m; ++i)
            sat[(j + 1) * (m + 1) + i + 1] = std::int32_t(cells[j * m + i]) + sat[j * (m + 1) + i + 1] +
                                             sat[(j + 1) * (m + 1) + i] - sat[j * (m + 1) + i];
    const auto anyMarked = [&](int i0, int j0, int i1, int j1) {  // inclusive
        const auto at = [&](int i, int j) { return sat[std::size_t(j) * (m + 1) + std::size_t(i)]; };
        return at(i1 + 1, j1 + 1) - at(i0, j1 + 1) - at(i1 + 1, j0) + at(i0, j0) > 0;
    };
    const std::uint32_t n2 = stride * stride;
    for (std::size_t k = 0; k + 2 < keys.size(); k += 3) {
        if (int(keys[k] / n2) != face) continue;  // a triangle's three keys are on one face
        int i0 = n, j0 = n, i1 = 0, j1 = 0;
        for (std::size_t c = 0; c < 3; ++c) {
            const std::uint32_t key = keys[k + c] % n2;
            const int i = std::min(int(key % stride), n - 1), j = std::min(int(key / stride), n - 1);
            i0 = std::min(i0, i), j0 = std::min(j0, j), i1 = std::max(i1, i), j1 = std::max(j1, j);
        }
        i1 = std::max(i0, i1 - 1), j1 = std::max(j0, j1 - 1);
        i0 = std::min(i0, n - 2), j0 = std::min(j0, n - 2), i1 = std::min(i1, n - 2), j1 = std::min(j1, n - 2);
        if (anyMarked(i0, j0, i1, j1)) testTriangle(vertices, w, keys[k], keys[k + 1], keys[k + 2], out);
    }
}

void sortByT(std::vector<VolumeCrossing>& out) {
    std::sort(out.begin(), out.end(), [](const VolumeCrossing& a, const VolumeCrossing& b) { return a.t < b.t; });
}

}  // namespace

std::vector<VolumeCrossing> volumeCrossings(const VolumeGrid& grid, const render::GpuLightCpu& light,
                                            const std::vector<float>& texels, const glm::dvec3& w,
                                            const std::vector<std::uint32_t>* adaptiveKeys) {
    VIZ_CHECK(grid.mode == kModeSpot || grid.mode == kModeDirectional, "volumeCrossings: 2D maps only");
    VIZ_CHECK(grid.keyStride == grid.mapSize + (adaptiveKeys ? 1 : 0), "volumeCrossings: key stride mismatch");
    const int n = grid.mapSize;
    VIZ_CHECK(n >= 2 && texels.size() == std::size_t(n) * std::size_t(n), "volumeCrossings: map size mismatch");
    VolumeVertices vertices(grid, light, {&texels, nullptr, nullptr, nullptr, nullptr, nullptr});
    std::vector<VolumeCrossing> out;
    const auto test = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) { testTriangle(vertices, w, a, b, c, out); };

    // Grid: only the cells along the ray's projection (and, for a directional map, the border ring, which
    // the skirt pushes out far beyond its texels' projections).
    const double reach = glm::length(glm::dvec3(light.position)) + std::abs(double(grid.noHit)) +
                         std::abs(double(grid.capDepth)) + 1.0;
    std::vector<char> cells(std::size_t(n) * std::size_t(n), 0);
    cellsAlongRay(glm::dmat4(light.shadowMatrix), w, n, 4.0 * reach, cells);
    if (grid.mode == kModeDirectional) {
        for (int k = 0; k <= n - 2; ++k) {
            cells[std::size_t(k)] = cells[std::size_t(n - 2) * std::size_t(n) + std::size_t(k)] = 1;
            cells[std::size_t(k) * std::size_t(n)] = cells[std::size_t(k) * std::size_t(n) + std::size_t(n - 2)] = 1;
        }
    }
    if (!adaptiveKeys) {
        for (int j = 0; j <= n - 2; ++j) {
            for (int i = 0; i <= n - 2; ++i) {
                if (!cells[std::size_t(j) * std::size_t(n) + std::size_t(i)]) continue;
                const std::uint32_t k00 = gridKey(n, 0, i, j), k10 = gridKey(n, 0, i + 1, j);
                const std::uint32_t k11 = gridKey(n, 0, i + 1, j + 1), k01 = gridKey(n, 0, i, j + 1);
                // As volume.vert: (00, 10, 11) and (00, 11, 01), counter-clockwise seen from the light.
                test(k00, k10, k11);
                test(k00, k11, k01);
            }
        }
    } else {
        // Adaptive triangles span quads of 2^k texels.
        testAdaptiveFace(vertices, w, cells, n, 0, std::uint32_t(grid.keyStride), *adaptiveKeys, out);
    }
    const std::vector<std::uint32_t> closure = gridClosure(grid.keyStride);
    for (std::size_t k = 0; k + 2 < closure.size(); k += 3) test(closure[k], closure[k + 1], closure[k + 2]);
    sortByT(out);
    return out;
}

std::vector<VolumeCrossing> cubeVolumeCrossings(const VolumeGrid& grid, const render::GpuLightCpu& light,
                                                const std::array<const std::vector<float>*, 6>& faces,
                                                const glm::dvec3& w, const std::vector<std::uint32_t>* adaptiveKeys) {
    VIZ_CHECK(grid.mode == kModeCube, "cubeVolumeCrossings: cube maps only");
    VIZ_CHECK(grid.keyStride == grid.mapSize + (adaptiveKeys ? 1 : 0), "cubeVolumeCrossings: key stride mismatch");
    const int n = grid.mapSize;
    for (const std::vector<float>* f : faces)
        VIZ_CHECK(f && f->size() == std::size_t(n) * std::size_t(n), "cubeVolumeCrossings: face size mismatch");
    VolumeVertices vertices(grid, light, faces);
    std::vector<VolumeCrossing> out;
    // Each face's grid along the ray's projection through that face's frustum (as ShadowMaps rendered it).
    const double reach = glm::length(glm::dvec3(light.position)) + std::abs(double(grid.noHit)) + 1.0;
    std::vector<char> cells(std::size_t(n) * std::size_t(n), 0);
    for (int face = 0; face < 6; ++face) {
        std::fill(cells.begin(), cells.end(), char(0));
        cellsAlongRay(render::shadowMapMatrix(light, face), w, n, 4.0 * reach, cells);
        if (adaptiveKeys) {
            testAdaptiveFace(vertices, w, cells, n, face, std::uint32_t(grid.keyStride), *adaptiveKeys, out);
            continue;
        }
        for (int j = 0; j <= n - 2; ++j) {
            for (int i = 0; i <= n - 2; ++i) {
                if (!cells[std::size_t(j) * std::size_t(n) + std::size_t(i)]) continue;
                const std::uint32_t k00 = gridKey(n, face, i, j), k10 = gridKey(n, face, i + 1, j);
                const std::uint32_t k11 = gridKey(n, face, i + 1, j + 1), k01 = gridKey(n, face, i, j + 1);
                testTriangle(vertices, w, k00, k10, k11, out);
                testTriangle(vertices, w, k00, k11, k01, out);
            }
        }
    }
    const std::vector<std::uint32_t> seams = cubeSeams(n, grid.keyStride);
    for (std::size_t k = 0; k + 2 < seams.size(); k += 3) testTriangle(vertices, w, seams[k], seams[k + 1], seams[k + 2], out);
    sortByT(out);
    return out;
}

}  // namespace viz::polyvol
