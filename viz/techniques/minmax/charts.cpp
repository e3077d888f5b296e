#include "techniques/minmax/charts.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "techniques/minmax/minmax_tree.h"

namespace viz::minmax {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

float greyOfBeta(float beta) { return beta < 0.0f ? 0.0f : std::min(beta / kPi, 1.0f); }

void setRgb(Image& img, int x, int y, glm::vec3 c) {
    for (int ch = 0; ch < 3; ++ch) img.at(x, y, ch) = c[ch];
}

}  // namespace

Image rectifiedView(const std::function<std::vector<float>(const std::vector<int>&)>& readRows, int columns,
                    int rows, int pickedRow) {
    const int vw = std::min(columns, 1024), vh = std::min(rows, 1024);
    Image img(vw, vh, 3);
    const int pickedY = int(static_cast<long long>(pickedRow) * vh / rows);
    std::vector<int> sources(static_cast<std::size_t>(vh));
    for (int y = 0; y < vh; ++y)
        sources[std::size_t(y)] = y == pickedY ? pickedRow : int(static_cast<long long>(y) * rows / vh);
    const std::vector<float> values = readRows(sources);
    VIZ_CHECK(values.size() == std::size_t(vh) * std::size_t(columns), "rectifiedView: readRows gave a wrong size");
    for (int y = 0; y < vh; ++y) {
        const bool picked = y == pickedY;
        const float* row = values.data() + std::size_t(y) * std::size_t(columns);
        for (int x = 0; x < vw; ++x) {
            const float grey = greyOfBeta(row[std::size_t(static_cast<long long>(x) * columns / vw)]);
            setRgb(img, x, y, picked ? glm::vec3(1.0f, 0.2f * grey, 0.2f * grey) : glm::vec3(grey));
        }
    }
    return img;
}

int pyramidBandRows(int width, int levels) { return std::max(4, 2 * (width / (6 * std::max(levels, 1)))); }

Image pyramidView(const std::vector<glm::vec2>& tree, int levelsBuilt) {
    const int n = int(tree.size() / 2);
    const int levels = std::bit_width(unsigned(n));  // log2(n) + 1
    const int width = std::min(n, kChartWidth);
    const int band = pyramidBandRows(width, levels);
    Image img(width, levels * band, 3);
    for (int l = 0; l < levels; ++l) {
        const bool built = l >= levels - 1 - levelsBuilt;  // the leaves (l = levels - 1) always are
        const long long count = 1LL << l;                  // nodes on level l, at tree[count .. 2 count)
        for (int x = 0; x < width; ++x) {
            // The nodes under pixel x: one (a level narrower than the image), or the pixel's share of a
            // wider level, merged as the level above would merge them (min of mins, max of maxes).
            const long long first = x * count / width;
            const long long last = std::max(first, (x + 1) * count / width - 1);
            glm::vec2 mm = tree[std::size_t(count + first)];
            for (long long k = first + 1; k <= last; ++k) {
                const glm::vec2 node = tree[std::size_t(count + k)];
                mm = {std::min(mm.x, node.x), std::max(mm.y, node.y)};
            }
            for (int b = 0; b < band; ++b) {
                const float grey = greyOfBeta(b < band / 2 ? mm.x : mm.y);
                setRgb(img, x, l * band + b, built ? glm::vec3(grey) : glm::vec3(0.0f, 0.0f, 0.5f));
            }
        }
    }
    return img;
}

Image traceView(const std::vector<glm::vec2>& tree, float beta, float cEnd, int steps) {
    const int n = int(tree.size() / 2);
    const int levels = std::bit_width(unsigned(n));
    // The heightfield and the node bands grow with the row, so that a long row is not a thin strip: about
    // 3:1 for 1024 columns (plot 170 px, bands of 15).
    const int plotH = std::clamp(n / 6, 128, 256), band = std::max(3, plotH / levels);
    Image img(n, plotH + levels * band, 3);
    // Vertical range: the row's finite S values and the ray's beta, padded by a tenth.
    float lo = beta, hi = beta;
    for (int x = 0; x < n; ++x) {
        const float S = tree[std::size_t(n + x)].x;
        if (S >= 0.0f && S <= kPi) lo = std::min(lo, S), hi = std::max(hi, S);
    }
    const float pad = 0.1f * std::max(hi - lo, 1e-3f);
    lo = std::max(0.0f, lo - pad);
    hi = std::min(kPi, hi + pad);
    auto yOf = [&](float b) { return std::clamp(int((1.0f - (b - lo) / (hi - lo)) * float(plotH - 1)), 0, plotH - 1); };
    const int yRay = yOf(beta);
    for (int x = 0; x < n; ++x) {
        const float S = tree[std::size_t(n + x)].x;
        for (int y = yOf(std::max(S, 0.0f)); y < plotH; ++y) setRgb(img, x, y, glm::vec3(0.35f));
        if (float(x) < cEnd) setRgb(img, x, yRay, glm::vec3(1.0f, 0.9f, 0.2f));
    }
    int step = 0;
    traverse(tree, beta, std::min(cEnd, float(n)), [](const LitRun&) {}, [&](const VisitedNode& v) {
        if (steps > 0 && step++ >= steps) return;
        const int l = std::bit_width(unsigned(v.node)) - 1;
        const NodeRange r = nodeRange(v.node, n);
        const glm::vec3 c = v.state == NodeState::Lit        ? glm::vec3(0.2f, 0.9f, 0.2f)
                            : v.state == NodeState::Shadowed ? glm::vec3(0.6f, 0.05f, 0.05f)
                                                             : glm::vec3(0.6f);
        for (int x = r.lo; x < r.hi; ++x)
            for (int b = 0; b < band - 1; ++b) setRgb(img, x, plotH + l * band + b, c);
    });
    return img;
}

int walkLength(const std::vector<glm::vec2>& tree, float beta, float cEnd) {
    int visited = 0;
    traverse(tree, beta, std::min(cEnd, float(tree.size() / 2)), [](const LitRun&) {}, [&](const VisitedNode&) { ++visited; });
    return visited;
}

Image singularValuesView(const LowRank& lr) {
    Image img(kGrid, 64, 3);
    const double top = std::log10(std::max(lr.singularValues.front(), 1e-300));
    for (int i = 0; i < kGrid; ++i) {
        const double v = std::log10(std::max(lr.singularValues[std::size_t(i)], 1e-300));
        const int height = std::clamp(int(64.0 * (1.0 - (top - v) / 12.0)), 0, 64);
        for (int y = 64 - height; y < 64; ++y)
            setRgb(img, i, y, i < lr.rank ? glm::vec3(0.2f, 0.9f, 0.2f) : glm::vec3(0.6f));
    }
    return img;
}

Image reconstructionErrorView(const LowRank& lr) {
    Image img(kGrid, kGrid, 1);
    double peak = 0.0;
    for (double v : lr.samples) peak = std::max(peak, std::abs(v));
    if (!(peak > 0.0)) return img;
    for (int k = 0; k < kGrid; ++k)
        for (int j = 0; j < kGrid; ++j)
            img.at(j, k, 0) = float(std::abs(lr.samples[std::size_t(k + kGrid * j)] - reconstruct(lr, k, j)) / peak);
    return img;
}

Image basisView(const LowRank& lr) {
    const int h = 64;
    Image img(kGrid, 2 * h, 3);
    const glm::vec3 colours[kMaxRank] = {{1, 0.2f, 0.2f}, {0.2f, 1, 0.2f}, {0.3f, 0.5f, 1}, {1, 1, 0.2f},
                                         {1, 0.2f, 1},    {0.2f, 1, 1},    {1, 0.6f, 0.2f}, {0.8f, 0.8f, 0.8f}};
    for (int half = 0; half < 2; ++half) {
        const std::vector<float>& v = half == 0 ? lr.basisB : lr.basisGamma;
        float m = 1e-30f;
        for (int k = 0; k < lr.rank * kGrid; ++k) m = std::max(m, std::abs(v[std::size_t(k)]));
        for (int i = 0; i < lr.rank; ++i)
            for (int k = 0; k < kGrid; ++k) {
                const float y = v[std::size_t(i * kGrid + k)] / m;  // [-1, 1]
                setRgb(img, k, half * h + std::clamp(int((0.5f - 0.5f * y) * float(h - 1)), 0, h - 1), colours[i]);
            }
    }
    return img;
}

PlotData singularValuesPlot(const LowRank& lr) {
    PlotData p;
    p.title = "singular values of I sin(beta), rank " + std::to_string(lr.rank) + " kept";
    p.xLabel = "i";
    p.yLabel = "sigma_i";
    p.logY = true;
    PlotCurve kept{"kept", {}, true, true, 2}, dropped{"dropped", {}, true, true, 7};
    for (int i = 0; i < int(lr.singularValues.size()); ++i) {
        const double s = lr.singularValues[std::size_t(i)];
        if (!(s > 0.0)) continue;  // a log axis has no place for zero
        (i < lr.rank ? kept : dropped).points.push_back({double(i + 1), s});
    }
    // The two curves meet: the first dropped value continues the kept line.
    if (!kept.points.empty() && !dropped.points.empty()) dropped.points.insert(dropped.points.begin(), kept.points.back());
    p.curves = {kept, dropped};
    return p;
}

std::vector<PlotData> basisPlots(const LowRank& lr, bool directional) {
    const auto degrees = [](double radians) { return radians * 180.0 / std::numbers::pi; };
    PlotData b, g;
    b.title = "B_i(beta) = s_i u_i";
    b.xLabel = "beta (degrees)";
    g.title = "Gamma_i(gamma) = v_i";
    g.xLabel = directional ? "gamma = rho (scene units)" : "gamma (degrees)";
    const auto gammaAxis = [&](double gamma) { return directional ? gamma : degrees(gamma); };
    for (int i = 0; i < lr.rank; ++i) {
        PlotCurve cb{"B_" + std::to_string(i + 1), {}, true, false, i}, cg{"Gamma_" + std::to_string(i + 1), {}, true, false, i};
        for (int k = 0; k < kGrid; ++k) {
            const double t = double(k) / double(kGrid - 1);
            cb.points.push_back({degrees(lr.betaLo + t * (lr.betaHi - lr.betaLo)), lr.basisB[std::size_t(i * kGrid + k)]});
            cg.points.push_back({gammaAxis(lr.gammaLo + t * (lr.gammaHi - lr.gammaLo)), lr.basisGamma[std::size_t(i * kGrid + k)]});
        }
        b.curves.push_back(std::move(cb));
        g.curves.push_back(std::move(cg));
    }
    return {b, g};
}

}  // namespace viz::minmax
