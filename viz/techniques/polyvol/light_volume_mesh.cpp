#include "techniques/polyvol/light_volume_mesh.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"

namespace viz::polyvol {
namespace {

// Face f of a cube: view direction and up of its lookAt (render::ShadowMaps::cubeFaceBasis).
void faceBasis(int face, glm::dvec3& forward, glm::dvec3& right, glm::dvec3& trueUp) {
    const int axis = face >> 1;
    const double s = (face & 1) == 0 ? 1.0 : -1.0;
    forward = glm::dvec3(0.0);
    forward[axis] = s;
    const glm::dvec3 up = axis == 1 ? glm::dvec3(0.0, 0.0, s) : glm::dvec3(0.0, -1.0, 0.0);
    right = glm::cross(forward, up);
    trueUp = glm::cross(right, forward);
}

glm::dvec3 keyDirection(int size, int stride, std::uint32_t key) {
    const std::uint32_t n2 = std::uint32_t(stride) * std::uint32_t(stride);
    const int face = int(key / n2);
    const std::uint32_t rest = key % n2;
    return cubeTexelDirection(size, face, double(rest % std::uint32_t(stride)), double(rest / std::uint32_t(stride)));
}

// Appends (a, b, c) counter-clockwise seen from the light at the origin: the normal of a CCW triangle
// points toward the viewer, here the light, i.e. against the directions of its vertices.
void addOriented(std::vector<std::uint32_t>& out, int size, int stride, std::uint32_t a, std::uint32_t b,
                 std::uint32_t c) {
    const glm::dvec3 da = keyDirection(size, stride, a), db = keyDirection(size, stride, b),
                     dc = keyDirection(size, stride, c);
    const glm::dvec3 n = glm::cross(db - da, dc - da);
    if (glm::dot(n, da + db + dc) < 0.0) {
        out.insert(out.end(), {a, b, c});
    } else {
        out.insert(out.end(), {a, c, b});
    }
}

}  // namespace

std::vector<std::uint32_t> gridClosure(int size) {
    VIZ_CHECK(size >= 2, "a light volume grid needs at least 2x2 texels");
    std::vector<std::uint32_t> keys;
    keys.reserve(std::size_t(4 * (size - 1)) * 9);
    auto edge = [&](int ai, int aj, int bi, int bj) {
        const std::uint32_t a = gridKey(size, 0, ai, aj), b = gridKey(size, 0, bi, bj);
        const std::uint32_t a2 = capKey(size, ai, aj), b2 = capKey(size, bi, bj);
        keys.insert(keys.end(), {b, a, a2, b, a2, b2, b2, a2, kApexKey});
    };
    const int last = size - 1;
    for (int i = 0; i < last; ++i) edge(i, 0, i + 1, 0);
    for (int j = 0; j < last; ++j) edge(last, j, last, j + 1);
    for (int i = last; i > 0; --i) edge(i, last, i - 1, last);
    for (int j = last; j > 0; --j) edge(0, j, 0, j - 1);
    return keys;
}

glm::dvec3 cubeTexelDirection(int size, int face, double i, double j) {
    glm::dvec3 forward, right, trueUp;
    faceBasis(face, forward, right, trueUp);
    const double x = 2.0 * (i + 0.5) / double(size) - 1.0;
    const double y = 2.0 * (j + 0.5) / double(size) - 1.0;
    return glm::normalize(forward + x * right + y * trueUp);
}

CubeTexel cubeTexelOf(int size, const glm::dvec3& d) {
    const glm::dvec3 a = glm::abs(d);
    const int axis = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
    const int face = 2 * axis + (d[axis] < 0.0 ? 1 : 0);
    glm::dvec3 forward, right, trueUp;
    faceBasis(face, forward, right, trueUp);
    const double f = glm::dot(forward, d);
    const glm::dvec2 ndc(glm::dot(right, d) / f, glm::dot(trueUp, d) / f);
    const auto texel = [&](double v) { return std::clamp(int(std::floor((v * 0.5 + 0.5) * size)), 0, size - 1); };
    return {face, texel(ndc.x), texel(ndc.y)};
}

std::vector<std::uint32_t> cubeSeams(int size, int keyStride) {
    VIZ_CHECK(size >= 2, "a light volume grid needs at least 2x2 texels");
    const int stride = keyStride > 0 ? keyStride : size;
    VIZ_CHECK(stride >= size, "cube seams: a key stride below the face size");
    std::vector<std::uint32_t> keys;
    const int last = size - 1;
    const double texelNdc = 2.0 / double(size);
    for (int faceA = 0; faceA < 6; ++faceA) {
        glm::dvec3 forward, right, trueUp;
        faceBasis(faceA, forward, right, trueUp);
        // Sides of the face: texel k along the side and the outward step in ndc.
        for (int side = 0; side < 4; ++side) {
            std::vector<std::uint32_t> rowA, rowB;
            int faceB = -1;
            for (int k = 0; k < size; ++k) {
                const int i = side == 0 ? k : side == 1 ? last : side == 2 ? k : 0;
                const int j = side == 0 ? 0 : side == 1 ? k : side == 2 ? last : k;
                const glm::dvec2 outward = side == 0 ? glm::dvec2(0, -1)
                                         : side == 1 ? glm::dvec2(1, 0)
                                         : side == 2 ? glm::dvec2(0, 1)
                                                     : glm::dvec2(-1, 0);
                const glm::dvec2 ndc(2.0 * (i + 0.5) / size - 1.0 + outward.x * texelNdc,
                                     2.0 * (j + 0.5) / size - 1.0 + outward.y * texelNdc);
                const CubeTexel b = cubeTexelOf(size, forward + ndc.x * right + ndc.y * trueUp);
                VIZ_CHECK(b.face != faceA, "cube seam: the step across a border stayed on its face");
                VIZ_CHECK(faceB < 0 || faceB == b.face, "cube seam: one border touches two faces");
                faceB = b.face;
                rowA.push_back(gridKey(stride, faceA, i, j));
                rowB.push_back(gridKey(stride, b.face, b.i, b.j));
            }
            if (faceB < faceA) continue;  // the same edge is walked from the other face too
            for (int k = 0; k + 1 < size; ++k) {
                addOriented(keys, size, stride, rowA[std::size_t(k)], rowA[std::size_t(k) + 1], rowB[std::size_t(k) + 1]);
                addOriented(keys, size, stride, rowA[std::size_t(k)], rowB[std::size_t(k) + 1], rowB[std::size_t(k)]);
            }
        }
    }
    // Corners: the three texels nearest the cube corner, one on each face meeting there.
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 s((corner & 1) ? -1.0 : 1.0, (corner & 2) ? -1.0 : 1.0, (corner & 4) ? -1.0 : 1.0);
        std::array<std::uint32_t, 3> tri{};
        for (int axis = 0; axis < 3; ++axis) {
            glm::dvec3 d = s;
            d[axis] *= 1.001;  // just inside face (axis, sign)
            const CubeTexel t = cubeTexelOf(size, d);
            tri[std::size_t(axis)] = gridKey(stride, t.face, t.i, t.j);
        }
        addOriented(keys, size, stride, tri[0], tri[1], tri[2]);
    }
    return keys;
}

}  // namespace viz::polyvol
