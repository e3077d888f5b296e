// Per-frame epipolar setup of one light on the CPU (double): the frame of epipolar.h, the slice count that
// keeps every camera ray within half a pixel of a slice, the alpha range the screen needs, the gamma range
// the shadow map covers, and where the epipole falls on the screen.
#pragma once

#include <algorithm>
#include <bit>

#include <glm/glm.hpp>

#include "render/host_device.h"
#include "scene/scene.h"
#include "techniques/minmax/epipolar.h"

namespace viz::minmax {

// GL 4.5's smallest allowed GL_MAX_TEXTURE_SIZE (the rectified map has one row per slice): enough for
// every ray within half a pixel of a slice wherever the farthest pixel is within 16384 / (2 pi) = 2607 px
// of the epipole (1280x960 with the epipole on a corner needs about 10,000).
inline constexpr int kMaxSlices = 16384;
inline constexpr int kMaxColumns = 4096;

// Gamma texels per slice for a wanted count: a power of two in [16, kMaxColumns] (the min-max tree's
// leaves; the tree has log2 of it levels).
inline int rectifiedColumns(int wanted) {
    return std::min(int(std::bit_ceil(unsigned(std::clamp(wanted, 16, kMaxColumns)))), kMaxColumns);
}

// The epipole (direction a) and the anti-epipole (-a) on the screen, in pixel coordinates with y = 0 the
// bottom row (GL), for a width x height image; `valid` is false for a direction behind the camera.
struct ScreenPoint {
    glm::dvec2 pixel{0.0};
    bool valid = false;
};
struct Epipoles {
    ScreenPoint epipole, antiEpipole;
};
Epipoles screenEpipoles(const scene::Camera& camera, int width, int height, glm::dvec3 axis);

// Whether the epipole or anti-epipole lies on the screen widened by `margin` (NDC units on each side).
// For plan(), which has no image size: a camera without a fixed aspect ratio is taken as 4:3.
bool epipoleNearScreen(const scene::Camera& camera, glm::dvec3 axis, double margin);

// The epipolar axis of a light (toward the light), eye-relative world space.
glm::dvec3 epipolarAxis(const scene::Light& light, glm::dvec3 eye);

// A spot or point light of the scene at the eye itself (render::atEye). Every camera ray then starts at the light, there is no epipolar axis
// (the frame's would be NaN), and minmax marches that light's rays instead of rectifying its map.
inline bool atEye(const scene::Light& light, glm::dvec3 eye) {
    return light.type != scene::LightType::Directional && light.type != scene::LightType::Area &&
           render::atEye(glm::vec3(light.position - eye));
}

struct SetupInput {
    const render::GpuLightCpu* light = nullptr;  // spot, point or directional, with its shadow matrix
    const scene::Camera* camera = nullptr;
    int width = 0, height = 0;
    int slices = 0;   // 0: automatic
    int columns = 0;  // gamma texels (rounded up to a power of two)
    int oversampling = 1;  // automatic slices: every camera ray within 1 / (2 oversampling) pixel of a slice
    // slice_frame=fixed: the slices at alpha = k 2 pi / 2^m about the axis, alpha measured from a
    // world-fixed direction (makeFrame's), the spacing a power-of-two division of the circle no coarser
    // than the screen needs: while the eye and the light stay on the same axis (the camera turning in
    // place, a spot turning about its position) the slices stay put in the world instead of following
    // the screen. false: the paper's grid, centred on the image centre's slice.
    bool fixedFrame = false;
    // true: alpha's and beta's ranges and alpha's smallest step are read off every pixel's ray; false
    // (default): off the image's border and the (anti-)epipole's pixels, where they occur (epipolar_setup.cpp,
    // sweepBorder), the same figures from about 6 (width + height) pixels instead of width x height.
    bool everyPixel = false;
};

struct Setup {
    EpipolarFrame<double> frame;
    double minAlphaGradient = 0.0;  // smallest |d alpha / d pixel| over the screen (radians per pixel)
    double maxSliceGap = 0.0;       // the largest distance (pixels) between neighbouring slices on screen
    double betaLo = 0.0, betaHi = 0.0;  // beta range of the pixels' rays
};

Setup setupLight(const SetupInput& in);

// The float frame uploaded to the shaders (and used by the CPU mirror).
EpipolarFrame<float> toFloat(const EpipolarFrame<double>& f);

}  // namespace viz::minmax
