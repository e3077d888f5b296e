// Area lights as cells: the emitter rectangle is split into N x N equal cells of its rectangle
// coordinates [0,1]^2; each cell has one visibility search (from its centre) and contributes the
// integral of its kernel over the whole cell, not a point sample of it.
//
// Why: a point node of weight dA has the kernel L_e cos(theta_e) p exp(-sigma_t r) dA / r^2, whose 1/r^2
// peak on an eye ray passing near the node is not there in the true emitter integral (which is bounded:
// int L_e cos(theta_e) / r^2 dA is at most 2 pi L_e). Averaging over the cell removes the spike.
//
// How: for one eye-ray segment (or one surface point) the cell is subdivided (quadtree in uv) until
// every leaf is at least kNearFactor leaf diameters from the segment; each leaf is integrated with an
// m x m product rule whose weights W_ab = int_leaf L_e(uv) l_a(u) l_b(v) dA hold the emission texture
// exactly (l = Lagrange basis on the leaf's m Gauss-Legendre nodes per axis; the bilinear texture is
// polynomial between texel-centre lines, so a composite Gauss rule split there integrates it exactly). The
// leaves depend on the segment, never on t, so along the ray each leaf node is an ordinary point
// emitter integrated exactly in t (pointEmitterSegment), and the t-integrals see no spike of a node
// the ray passes close to: such nodes belong to small leaves with small weights.
//
// Coordinate spaces: uv = rectangle coordinates in [0,1]^2 (uv (0,0) at position - halfU - halfV,
// u along halfU, v along halfV); positions and distances in world units.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "techniques/reference/linear_texture.h"

namespace viz::reference {

// Gauss-Legendre nodes per axis of each leaf (the product rule is exact for emission texture times
// a kernel that is a polynomial of degree m - 1 per axis over the leaf): kLeafOrderFar for leaves at
// least kFarOrderFactor leaf diameters from the segment, kLeafOrderNear for the others.
constexpr int kLeafOrderNear = 3;
constexpr int kLeafOrderFar = 2;
constexpr double kFarOrderFactor = 6.0;
// A leaf is accepted when its distance to the segment is at least this many leaf diameters.
constexpr double kNearFactor = 2.0;
// Leaves smaller than this fraction of the emitter's diagonal are not split further; those still near
// the segment are left out (their share is of the order of their size relative to the cell's).
constexpr double kMinLeafFraction = 1e-5;
// Upper bound on the leaves of one cell for one segment (a ray grazing the emitter at a tiny height).
constexpr int kMaxLeaves = 4096;

// The world placement and emission of one area light (scene::Light of type Area).
struct AreaEmitter {
    int light = -1;
    glm::dvec3 corner{0.0};            // world position of uv (0, 0)
    glm::dvec3 edgeU{0.0}, edgeV{0.0};  // 2 halfU, 2 halfV
    glm::dvec3 normal{0.0};            // unit; the light emits into dot(normal, x - corner) > 0
    glm::dvec3 radiance{0.0};          // L_e without the texture
    const LinearTexture* texture = nullptr;  // emission texture or null
    double area = 0.0;                 // |edgeU x edgeV|
    double diagonal = 0.0;             // |edgeU + edgeV|

    static AreaEmitter fromLight(const scene::Light& light, int index, const std::vector<LinearTexture>& textures);
    glm::dvec3 position(glm::dvec2 uv) const { return corner + uv.x * edgeU + uv.y * edgeV; }
    glm::dvec3 emitted(glm::dvec2 uv) const;  // L_e(uv), RGB
};

// One node of a cell's rule: a point source at `position` with RGB weight W (L_e-weighted area).
struct CellNode {
    glm::dvec3 position{0.0};
    glm::dvec3 weight{0.0};
};

struct AreaCell {
    const AreaEmitter* emitter = nullptr;
    glm::dvec2 uv0{0.0}, uv1{1.0};   // the cell in rectangle coordinates
    std::vector<CellNode> farNodes;   // the unsplit cell's kLeafOrderFar rule
    std::vector<CellNode> nearNodes;  // the unsplit cell's kLeafOrderNear rule
};

// The product rule of the leaf [uv0, uv1] (order^2 nodes, texture integrated exactly); order 1..4.
std::vector<CellNode> leafNodes(const AreaEmitter& emitter, glm::dvec2 uv0, glm::dvec2 uv1, int order);

// The nodes of a cell's rule for the segment p0 -> p1 (p0 == p1: one point), refined towards it.
std::vector<CellNode> cellNodes(const AreaCell& cell, const glm::dvec3& p0, const glm::dvec3& p1);

// Irradiance at a surface point x with unit normal n from the cell, through the medium:
// int_cell L_e cos(theta_e) max(0, dot(n, l)) exp(-sigma_t r) / r^2 dA.
glm::dvec3 cellIrradiance(const AreaCell& cell, const glm::dvec3& x, const glm::dvec3& n, double sigma_t);

}  // namespace viz::reference
