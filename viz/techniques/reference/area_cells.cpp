#include "techniques/reference/area_cells.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.h"
#include "shared/gauss_legendre.h"

namespace viz::reference {

namespace {

// Gauss-Legendre rules on [0, 1] with 1..4 nodes (built once; reading them is thread-safe).
const QuadratureRule& unitRule(int n) {
    static const std::vector<QuadratureRule> rules = [] {
        std::vector<QuadratureRule> r;
        for (int k = 1; k <= 4; ++k) r.push_back(gaussLegendreRuleUnit(k));
        return r;
    }();
    VIZ_CHECK(n >= 1 && n <= 4, "leaf rules have 1 to 4 nodes per axis");
    return rules[std::size_t(n - 1)];
}

// Points and weights (in uv units) of the composite Gauss rule over [lo, hi], split where the bilinear
// texture has its kinks: the texel-centre lines (i + 0.5) / texels.
// Texture (linear per axis between texel-centre lines) times a Lagrange basis of degree m - 1 is a
// polynomial of degree m per axis, which m / 2 + 1 Gauss points per piece integrate exactly.
void compositeRule(double lo, double hi, int texels, int order, std::vector<double>& x, std::vector<double>& wt) {
    std::vector<double> cuts{lo};
    // First texel-centre line above lo, then every one up to hi.
    for (int i = std::max(0, int(std::floor(lo * texels - 0.5))); i < texels; ++i) {
        const double c = (double(i) + 0.5) / double(texels);
        if (c >= hi) break;
        if (c > lo) cuts.push_back(c);
    }
    cuts.push_back(hi);
    const QuadratureRule& rule = unitRule(order / 2 + 1);
    for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
        const double len = cuts[p + 1] - cuts[p];
        for (std::size_t k = 0; k < rule.nodes.size(); ++k) {
            x.push_back(cuts[p] + len * rule.nodes[k]);
            wt.push_back(len * rule.weights[k]);
        }
    }
}

// Lagrange basis l_a(s) on the leaf's nodes (in the leaf's own [0, 1] coordinate).
double lagrange(const QuadratureRule& rule, std::size_t a, double s) {
    double v = 1.0;
    for (std::size_t b = 0; b < rule.nodes.size(); ++b)
        if (b != a) v *= (s - rule.nodes[b]) / (rule.nodes[a] - rule.nodes[b]);
    return v;
}

double pointSegmentDistance(const glm::dvec3& c, const glm::dvec3& p0, const glm::dvec3& p1) {
    const glm::dvec3 d = p1 - p0;
    const double len2 = glm::dot(d, d);
    const double s = len2 > 0.0 ? std::clamp(glm::dot(c - p0, d) / len2, 0.0, 1.0) : 0.0;
    return glm::length(c - (p0 + s * d));
}

}  // namespace

AreaEmitter AreaEmitter::fromLight(const scene::Light& light, int index,
                                   const std::vector<LinearTexture>& textures) {
    VIZ_CHECK(light.type == scene::LightType::Area, "AreaEmitter needs an area light");
    AreaEmitter e;
    e.light = index;
    e.corner = light.position - light.halfU - light.halfV;
    e.edgeU = 2.0 * light.halfU;
    e.edgeV = 2.0 * light.halfV;
    e.normal = glm::normalize(light.direction);
    e.radiance = light.radiance;
    if (light.emissionTexture >= 0 && std::size_t(light.emissionTexture) < textures.size() &&
        !textures[std::size_t(light.emissionTexture)].empty())
        e.texture = &textures[std::size_t(light.emissionTexture)];
    e.area = glm::length(glm::cross(e.edgeU, e.edgeV));
    e.diagonal = glm::length(e.edgeU + e.edgeV);
    return e;
}

glm::dvec3 AreaEmitter::emitted(glm::dvec2 uv) const {
    return texture ? radiance * texture->sample(uv) : radiance;
}

std::vector<CellNode> leafNodes(const AreaEmitter& emitter, glm::dvec2 uv0, glm::dvec2 uv1, int order) {
    const QuadratureRule& rule = unitRule(order);
    const std::size_t m = rule.nodes.size();
    const glm::dvec2 size = uv1 - uv0;
    const double leafArea = emitter.area * size.x * size.y;
    std::vector<CellNode> nodes(m * m);
    for (std::size_t b = 0; b < m; ++b)
        for (std::size_t a = 0; a < m; ++a)
            nodes[b * m + a].position = emitter.position(uv0 + size * glm::dvec2(rule.nodes[a], rule.nodes[b]));
    if (!emitter.texture) {
        for (std::size_t b = 0; b < m; ++b)
            for (std::size_t a = 0; a < m; ++a)
                nodes[b * m + a].weight = emitter.radiance * (leafArea * rule.weights[a] * rule.weights[b]);
        return nodes;
    }
    // W_ab = A int int L_e(u, v) l_a(u) l_b(v) du dv over the leaf (u, v in the leaf's [0,1]^2), by the
    // composite rule that is exact between texel-centre lines.
    std::vector<double> su, wu, sv, wv;
    compositeRule(uv0.x, uv1.x, emitter.texture->width(), order, su, wu);
    compositeRule(uv0.y, uv1.y, emitter.texture->height(), order, sv, wv);
    std::vector<double> lu(m * su.size()), lv(m * sv.size());
    for (std::size_t a = 0; a < m; ++a) {
        for (std::size_t k = 0; k < su.size(); ++k)
            lu[a * su.size() + k] = lagrange(rule, a, (su[k] - uv0.x) / size.x);
        for (std::size_t k = 0; k < sv.size(); ++k)
            lv[a * sv.size() + k] = lagrange(rule, a, (sv[k] - uv0.y) / size.y);
    }
    std::vector<glm::dvec3> row(m);
    for (std::size_t l = 0; l < sv.size(); ++l) {
        std::fill(row.begin(), row.end(), glm::dvec3(0.0));
        for (std::size_t k = 0; k < su.size(); ++k) {
            const glm::dvec3 le = emitter.emitted(glm::dvec2(su[k], sv[l])) * wu[k];
            for (std::size_t a = 0; a < m; ++a) row[a] += lu[a * su.size() + k] * le;
        }
        for (std::size_t b = 0; b < m; ++b) {
            const double f = wv[l] * lv[b * sv.size() + l];
            for (std::size_t a = 0; a < m; ++a) nodes[b * m + a].weight += f * row[a];
        }
    }
    // The weights above are in uv units (du dv over the leaf); dA = A du dv.
    for (CellNode& node : nodes) node.weight *= emitter.area;
    return nodes;
}

std::vector<CellNode> cellNodes(const AreaCell& cell, const glm::dvec3& p0, const glm::dvec3& p1) {
    VIZ_CHECK(cell.emitter != nullptr, "AreaCell without an emitter");
    const AreaEmitter& e = *cell.emitter;
    struct Leaf {
        glm::dvec2 uv0, uv1;
    };
    auto diameter = [&](const Leaf& leaf) {
        return glm::length((leaf.uv1.x - leaf.uv0.x) * e.edgeU + (leaf.uv1.y - leaf.uv0.y) * e.edgeV);
    };
    // The leaf's distance to the segment in leaf diameters (centre distance minus half the diameter, a
    // lower bound of its nearest point's distance).
    auto separation = [&](const Leaf& leaf) {
        const double d = diameter(leaf);
        return (pointSegmentDistance(e.position(0.5 * (leaf.uv0 + leaf.uv1)), p0, p1) - 0.5 * d) / d;
    };
    const Leaf whole{cell.uv0, cell.uv1};
    const double wholeSeparation = separation(whole);
    if (wholeSeparation >= kFarOrderFactor) return cell.farNodes;
    if (wholeSeparation >= kNearFactor) return cell.nearNodes;

    // Breadth first, so that the leaf bound stops the finest levels, not one branch.
    std::vector<CellNode> out;
    std::vector<Leaf> level{whole}, next;
    const double minDiameter = kMinLeafFraction * e.diagonal;
    int leaves = 1;
    while (!level.empty()) {
        next.clear();
        for (const Leaf& leaf : level) {
            const bool capped = leaves + 3 > kMaxLeaves;
            const double s = separation(leaf);
            if (s >= kNearFactor || capped) {
                const int order = s >= kFarOrderFactor ? kLeafOrderFar : kLeafOrderNear;
                const std::vector<CellNode> nodes = leafNodes(e, leaf.uv0, leaf.uv1, order);
                out.insert(out.end(), nodes.begin(), nodes.end());
                continue;
            }
            // Near and already tiny: left out (its share of the cell is about its size over the cell's).
            if (diameter(leaf) < minDiameter) continue;
            const glm::dvec2 mid = 0.5 * (leaf.uv0 + leaf.uv1);
            next.push_back({leaf.uv0, mid});
            next.push_back({{mid.x, leaf.uv0.y}, {leaf.uv1.x, mid.y}});
            next.push_back({{leaf.uv0.x, mid.y}, {mid.x, leaf.uv1.y}});
            next.push_back({mid, leaf.uv1});
            leaves += 3;
        }
        std::swap(level, next);
    }
    return out;
}

glm::dvec3 cellIrradiance(const AreaCell& cell, const glm::dvec3& x, const glm::dvec3& n, double sigma_t) {
    const glm::dvec3 normal = cell.emitter->normal;
    glm::dvec3 sum(0.0);
    for (const CellNode& node : cellNodes(cell, x, x)) {
        const glm::dvec3 toX = x - node.position;
        const double r = glm::length(toX);
        if (!(r > 0.0)) continue;
        const double cosE = glm::dot(normal, toX) / r;
        const double cosS = -glm::dot(n, toX) / r;
        if (cosE <= 0.0 || cosS <= 0.0) continue;
        sum += node.weight * (cosE * cosS * std::exp(-sigma_t * r) / (r * r));
    }
    return sum;
}

}  // namespace viz::reference
