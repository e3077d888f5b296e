#include "techniques/minmax/epipolar_setup.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "core/error.h"
#include "render/host_device.h"
#include "scene/camera.h"

namespace viz::minmax {
namespace {

// NDC of a direction q in front of the camera (x right, y up, both in [-1, 1] on screen).
bool ndcOf(const scene::Camera& cam, double aspect, glm::dvec3 q, glm::dvec2& ndc) {
    const double z = glm::dot(q, cam.forward);
    if (z <= 0.0) return false;
    const double tanHalf = std::tan(cam.yfov * 0.5);
    ndc = glm::dvec2(glm::dot(q, scene::cameraRight(cam)) / (z * tanHalf * aspect), glm::dot(q, cam.up) / (z * tanHalf));
    return true;
}

// alpha's and beta's ranges over the pixels' rays, and alpha's smallest change from a pixel to its left
// and upper neighbours.
struct PixelSweep {
    double alphaLo = std::numeric_limits<double>::max(), alphaHi = std::numeric_limits<double>::lowest();
    double betaLo = std::numbers::pi, betaHi = 0.0;
    double minGradient = std::numeric_limits<double>::max();

    void join(const PixelSweep& o) {
        alphaLo = std::min(alphaLo, o.alphaLo);
        alphaHi = std::max(alphaHi, o.alphaHi);
        betaLo = std::min(betaLo, o.betaLo);
        betaHi = std::max(betaHi, o.betaHi);
        minGradient = std::min(minGradient, o.minGradient);
    }
    // One pixel: its ray's alpha a and beta b, and (when it has both) the steps gx, gy to its neighbours.
    void add(double a, double b) {
        betaLo = std::min(betaLo, b);
        betaHi = std::max(betaHi, b);
        alphaLo = std::min(alphaLo, a);
        alphaHi = std::max(alphaHi, a);
    }
    void addSteps(double gx, double gy) { minGradient = std::min(minGradient, std::sqrt(gx * gx + gy * gy)); }
};

// Every pixel. 1920x1080 is two million rays with two atan2 each (about 200 ms on one core), so blocks of
// rows run in parallel (oneTBB); a block first computes the row above its own, so every pixel is compared
// with the same neighbours as in one pass, and min and max give the same figures whatever the split.
PixelSweep sweepEveryPixel(const EpipolarFrame<double>& f, const scene::PixelRays& rays, int width, int height) {
    const auto rows = [&](const tbb::blocked_range<int>& r, PixelSweep s) {
        std::vector<double> previousRow(std::size_t(width), 0.0);
        if (r.begin() > 0)
            for (int x = 0; x < width; ++x) previousRow[std::size_t(x)] = alphaOf(f, rays(x, r.begin() - 1));
        for (int y = r.begin(); y < r.end(); ++y) {
            double left = 0.0;
            for (int x = 0; x < width; ++x) {
                const glm::dvec3 ray = rays(x, y);
                const double a = alphaOf(f, ray);
                s.add(a, betaOf(f, ray));
                if (x > 0 && y > 0) s.addSteps(alphaStep(left, a), alphaStep(previousRow[std::size_t(x)], a));
                left = a;
                previousRow[std::size_t(x)] = a;
            }
        }
        return s;
    };
    return tbb::parallel_reduce(tbb::blocked_range<int>(0, height), PixelSweep{}, rows, [](PixelSweep a, const PixelSweep& b) {
        a.join(b);
        return a;
    });
}

// The same figures from the pixels where they can occur. On the image plane alpha is constant along each
// line through the epipole (or the anti-epipole; parallel lines when neither is finite), so in polar
// coordinates (r, theta) about that point alpha = F(theta) and |grad alpha| = |F'(theta)| / r: along each
// such line it falls (or stays) away from the point, and its smallest value over the image lies on the
// border; so do alpha's extremes when the epipole is off screen (on screen the slices wrap and alpha's
// range is not used). beta, the angle from the axis, has no critical point on the image plane but the
// epipole (its minimum) and the anti-epipole (its maximum), so its extremes lie on the border or next to
// those. So: a band kBand pixels wide along the border (the steps are finite differences, so a smallest
// one may sit a pixel or two in from the border) and a block around each (anti-)epipole on screen. In the
// tests' exhaustive comparisons (tests/cpu/minmax/epipolar_sweep_test.cpp) these give every pixel's
// figures bit for bit, from about 6 (width + height) pixels instead of width x height.
constexpr int kBand = 3, kBlock = 3;

PixelSweep sweepBorder(const EpipolarFrame<double>& f, const scene::PixelRays& rays, int width, int height,
                       const Epipoles& ep) {
    PixelSweep s;
    const auto visit = [&](int x, int y) {
        const glm::dvec3 ray = rays(x, y);
        const double a = alphaOf(f, ray);
        s.add(a, betaOf(f, ray));
        if (x > 0 && y > 0)
            s.addSteps(alphaStep(alphaOf(f, rays(x - 1, y)), a), alphaStep(alphaOf(f, rays(x, y - 1)), a));
    };
    for (int y = 0; y < height; ++y) {
        const bool whole = y < kBand || y >= height - kBand;
        for (int x = 0; x < width; ++x) {
            if (!whole && x == kBand) x = width - kBand;
            visit(x, y);
        }
    }
    for (const ScreenPoint& p : {ep.epipole, ep.antiEpipole}) {
        // screenEpipoles counts y up from the bottom with pixel i's centre at i + 1/2; rays counts rows down.
        const double cx = p.pixel.x - 0.5, cy = double(height) - p.pixel.y - 0.5;
        if (!p.valid || !(cx > -kBlock - 1.0 && cx < width + kBlock && cy > -kBlock - 1.0 && cy < height + kBlock))
            continue;
        const int x0 = std::max(0, int(std::floor(cx)) - kBlock);
        const int x1 = std::min(width, int(std::ceil(cx)) + kBlock + 1);
        const int y0 = std::max(0, int(std::floor(cy)) - kBlock);
        const int y1 = std::min(height, int(std::ceil(cy)) + kBlock + 1);
        for (int y = y0; y < y1; ++y)
            for (int x = x0; x < x1; ++x) visit(x, y);
    }
    return s;
}

// slice_frame=screen (the paper's grid), in the frame centred on the image centre's slice: alpha over the
// screen's [lo, hi] (or the whole circle when it wraps).
void paperSliceGrid(EpipolarFrame<double>& f, const SetupInput& in, double lo, double hi, double span,
                    double minGradient) {
    const double pi = std::numbers::pi;
    // Neighbouring slices at most one pixel apart wherever alpha changes slowest: every ray is within half
    // a pixel of its nearest slice.
    // Automatic grids also put a slice on alpha = 0, the half-plane of the image centre's ray: pixels on
    // that screen line (the centre line through the epipole) then use their own slice instead of lying
    // exactly halfway between two, where rounding would pick the side. An occluder whose boundary is an
    // epipolar plane through the eye and the centre ray (a plate with one face through the light, seen
    // from a camera in the same plane) keeps its shadow on the correct side of that line.
    const bool automatic = in.slices <= 0;
    int slices = in.slices;
    // The count wanted, in double: a tiny gradient asks for more than an int holds; the cap applies anyway.
    if (automatic)
        slices = int(std::min(std::ceil(span * std::max(1, in.oversampling) / minGradient), double(kMaxSlices))) +
                 (f.wrap ? 0 : 1);
    f.slices = std::clamp(slices, 2, kMaxSlices);
    if (f.wrap) {
        // An even count has slices at -pi + k 2 pi / n, among them 0 (k = n / 2).
        if (automatic && f.slices % 2 == 1) f.slices = std::min(f.slices + 1, kMaxSlices);
        f.alphaLo = -pi;
        f.alphaSpacing = 2.0 * pi / f.slices;
    } else {
        f.alphaLo = lo - minGradient;
        f.alphaSpacing = span / double(f.slices - 1);
        if (automatic) {
            // Same spacing, the grid shifted onto multiples of it (one more slice covers the shift).
            const double first = std::floor(f.alphaLo / f.alphaSpacing);
            const int count = int(std::ceil((hi + minGradient) / f.alphaSpacing) - first) + 1;
            if (count <= kMaxSlices) {
                f.alphaLo = first * f.alphaSpacing;
                f.slices = std::max(count, 2);
            }
        }
    }
}

// slice_frame=fixed (SetupInput::fixedFrame): the spacing is 2 pi / 2^m, the coarsest such no wider than
// what the paper's grid would use (so every ray stays as close to a slice), and the slices sit on its
// multiples in the world-fixed frame. The frame is then turned by the multiple of the spacing nearest the
// image centre's alpha, which moves no slice, so that the screen's alpha range stays one interval.
void fixedSliceGrid(EpipolarFrame<double>& f, const EpipolarFrame<double>& world, glm::dvec3 centre,
                    const SetupInput& in, double lo, double hi, double span, double minGradient) {
    const double pi = std::numbers::pi;
    double wanted;
    if (in.slices <= 0) wanted = minGradient / double(std::max(1, in.oversampling));
    else wanted = f.wrap ? 2.0 * pi / double(std::max(in.slices, 2)) : span / double(std::max(in.slices - 1, 1));
    const double asked = std::min(std::ceil(2.0 * pi / std::max(wanted, 1e-9)), double(kMaxSlices));
    int divisions = int(std::min<unsigned>(std::bit_ceil(unsigned(asked)), unsigned(kMaxSlices)));
    divisions = std::max(divisions, 2);
    // f (the centred frame) is the world frame turned by the centre's alpha a0; turning f back by
    // delta = a0 - k spacing gives a frame whose multiples of spacing are the world frame's.
    const double a0 = alphaOf(world, centre);
    for (;; divisions /= 2) {
        const double spacing = 2.0 * pi / double(divisions);
        const double delta = a0 - std::round(a0 / spacing) * spacing;
        EpipolarFrame<double> g = f;
        const double c = std::cos(-delta), sn = std::sin(-delta);
        g.u = c * f.u + sn * f.v;
        g.v = glm::cross(g.axis, g.u);
        g.alphaSpacing = spacing;
        if (g.wrap) {
            g.alphaLo = -pi;
            g.slices = divisions;
        } else {
            // Alpha in g = alpha in the centred frame + delta.
            const double first = std::floor((lo + delta - minGradient) / spacing);
            const int count = int(std::ceil((hi + delta + minGradient) / spacing) - first) + 1;
            if (count > kMaxSlices && divisions > 2) continue;
            g.alphaLo = first * spacing;
            g.slices = std::clamp(count, 2, kMaxSlices);
        }
        f = g;
        return;
    }
}

}  // namespace

Epipoles screenEpipoles(const scene::Camera& camera, int width, int height, glm::dvec3 axis) {
    const double aspect = scene::aspectOf(camera, width, height);
    Epipoles e;
    glm::dvec2 ndc;
    // pixelRay: ndcX = 2 (x + 1/2) / width - 1 with x the column; GL y counts from the bottom the same way.
    auto toPixel = [&](glm::dvec2 n) { return glm::dvec2((n.x + 1.0) * 0.5 * width, (n.y + 1.0) * 0.5 * height); };
    if (ndcOf(camera, aspect, axis, ndc)) e.epipole = {toPixel(ndc), true};
    if (ndcOf(camera, aspect, -axis, ndc)) e.antiEpipole = {toPixel(ndc), true};
    return e;
}

bool epipoleNearScreen(const scene::Camera& camera, glm::dvec3 axis, double margin) {
    const double aspect = camera.aspectRatio > 0.0 ? camera.aspectRatio : 4.0 / 3.0;
    for (double s : {1.0, -1.0}) {
        glm::dvec2 ndc;
        if (ndcOf(camera, aspect, s * axis, ndc) && std::abs(ndc.x) <= 1.0 + margin && std::abs(ndc.y) <= 1.0 + margin)
            return true;
    }
    return false;
}

glm::dvec3 epipolarAxis(const scene::Light& light, glm::dvec3 eye) {
    if (light.type == scene::LightType::Directional) return -glm::normalize(light.direction);
    return glm::normalize(light.position - eye);
}

Setup setupLight(const SetupInput& in) {
    VIZ_CHECK(in.light && in.camera && in.width > 0 && in.height > 0, "setupLight needs a light, a camera and a size");
    const render::GpuLightCpu& L = *in.light;
    const bool directional = L.info.x == render::hd::kLightDirectional;
    const bool point = L.info.x == render::hd::kLightPoint;
    const scene::Camera& cam = *in.camera;
    Setup s;
    EpipolarFrame<double>& f = s.frame;
    f = makeFrame<double>(directional ? LightKind::Directional : point ? LightKind::Point : LightKind::Spot,
                          glm::dvec3(L.position), glm::dvec3(L.direction));
    const glm::dvec3 centre = scene::pixelRay(cam, in.width, in.height, 0.5 * (in.width - 1), 0.5 * (in.height - 1));
    const EpipolarFrame<double> world = f;  // alpha from makeFrame's world-fixed direction
    centreAlphaOn(f, centre);

    // alpha over the pixels: its range, and its smallest change per pixel (where slices are sparsest).
    const double pi = std::numbers::pi;
    const scene::PixelRays rays(cam, in.width, in.height);
    const Epipoles ep = screenEpipoles(cam, in.width, in.height, f.axis);
    const bool border = !in.everyPixel && in.width > 2 * kBand && in.height > 2 * kBand;
    const PixelSweep sweep = border ? sweepBorder(f, rays, in.width, in.height, ep)
                                    : sweepEveryPixel(f, rays, in.width, in.height);
    const double lo = sweep.alphaLo, hi = sweep.alphaHi, betaLo = sweep.betaLo, betaHi = sweep.betaHi;
    double minGradient = sweep.minGradient;
    // An image one pixel wide or tall has no neighbour across it: the rays one pixel beyond the image (to
    // the left, above) stand in, so that its slices are as far apart as in a wider image's first column.
    if (in.width == 1 || in.height == 1)
        for (int y = 0; y < in.height; ++y)
            for (int x = 0; x < in.width; ++x) {
                const double a = alphaOf(f, rays(x, y));
                const double gx = alphaStep(alphaOf(f, rays(x - 1.0, y)), a);
                const double gy = alphaStep(alphaOf(f, rays(x, y - 1.0)), a);
                minGradient = std::min(minGradient, std::sqrt(gx * gx + gy * gy));
            }
    if (!(minGradient > 1e-9) || minGradient == std::numeric_limits<double>::max()) minGradient = 1e-9;
    s.minAlphaGradient = minGradient;
    s.betaLo = betaLo;
    s.betaHi = betaHi;
    auto onScreen = [&](const ScreenPoint& p) {
        return p.valid && p.pixel.x >= -1.0 && p.pixel.x <= in.width + 1.0 && p.pixel.y >= -1.0 &&
               p.pixel.y <= in.height + 1.0;
    };
    // With the epipole on screen the slices fan all the way round; otherwise the screen sees less than pi.
    f.wrap = onScreen(ep.epipole) || onScreen(ep.antiEpipole) || hi - lo > 0.9 * pi;
    const double span = f.wrap ? 2.0 * pi : (hi - lo) + 2.0 * minGradient;
    if (in.fixedFrame)
        fixedSliceGrid(f, world, centre, in, lo, hi, span, minGradient);
    else
        paperSliceGrid(f, in, lo, hi, span, minGradient);
    s.maxSliceGap = f.alphaSpacing / minGradient;

    // gamma: the spot's cone as seen from the light (angle phi between -a and the spot axis, +- outer), or
    // the directional map's reach (its box corners' largest distance from the axis). A point light's rows
    // each get the range their pixels' rays reach, [0, gamma(beta, d)], measured on the GPU from the
    // distance buffer (shaders/minmax/gamma_range.comp); [0, pi] here bounds every row.
    if (point) {
        f.gammaLo = 0.0;
        f.gammaHi = pi;
    } else if (directional) {
        const glm::dmat4 inv = glm::inverse(glm::dmat4(L.shadowMatrix));
        double reach = 0.0;
        for (int c = 0; c < 8; ++c) {
            glm::dvec4 p = inv * glm::dvec4((c & 1) ? 1.0 : -1.0, (c & 2) ? 1.0 : -1.0, (c & 4) ? 1.0 : -1.0, 1.0);
            const glm::dvec3 q = glm::dvec3(p) / p.w;
            reach = std::max(reach, glm::length(glm::cross(q, f.axis)));
        }
        f.gammaLo = 0.0;
        f.gammaHi = reach;
    } else {
        const double phi = std::acos(std::clamp(glm::dot(-f.axis, glm::dvec3(L.direction)), -1.0, 1.0));
        const double outer = std::acos(std::clamp(double(L.spot.w), -1.0, 1.0));
        f.gammaLo = std::max(0.0, phi - outer);
        f.gammaHi = std::min(pi, phi + outer);
    }
    f.columns = rectifiedColumns(in.columns);
    return s;
}

EpipolarFrame<float> toFloat(const EpipolarFrame<double>& f) {
    EpipolarFrame<float> g;
    g.kind = f.kind;
    g.axis = glm::vec3(f.axis);
    g.u = glm::vec3(f.u);
    g.v = glm::vec3(f.v);
    g.lightDistance = float(f.lightDistance);
    g.slices = f.slices;
    g.columns = f.columns;
    g.wrap = f.wrap;
    g.alphaLo = float(f.alphaLo);
    g.alphaSpacing = float(f.alphaSpacing);
    g.gammaLo = float(f.gammaLo);
    g.gammaHi = float(f.gammaHi);
    return g;
}

}  // namespace viz::minmax
