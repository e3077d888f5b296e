// minmax's `integrand=auto` (the default): which of the two integrands a scene gets, decided by plan()
// before any GL object exists, and why.
//
// Speed (measured, README "Integrands", auto): the svd integrand's lit run is two prefix-table lookups per
// layer; the analytic one is a closed form for a sun, one segment integral (Gauss-Legendre panels) per cone
// part for a spot without a cookie, and one per cookie cell for a spot with one. With suns alone the closed
// form is the cheaper traverse and svd's SVD and prefix sums only add to rectify, so auto takes analytic
// there without factorising anything; with any spot or point light svd is the faster one (grate's spot
// 1.2x to 1.35x at 640x480 to 1280x720, stained-glass's cookie about 5x) and auto takes it where it holds.
// Accuracy: svd is exact only for an integrand of rank N that its 64 x 64 grid and its prefix tables resolve.
// Each epipolar light's integrand is factorised over the frame the screen needs (its beta and gamma ranges)
// as the rectify stage does, and the tables are checked where they were not fitted (low_rank.h,
// rowIntegralError: fully lit rays between the grid's betas against the segment integral); where they are
// more than kAutoSvdLimit off, the image would carry that error, and auto takes the analytic integrand.
#pragma once

#include <mutex>
#include <string>

#include "scene/scene.h"

namespace viz::minmax {

// The largest rank-N reconstruction error auto accepts for svd.
inline constexpr double kAutoSvdLimit = 0.01;

struct IntegrandChoice {
    bool svd = false;
    double worstError = 0.0;  // the largest rowIntegralError over the epipolar lights (0: none)
    std::string worstLight;   // the light it belongs to
    std::string why;          // one line for the plan
};

// `marchPoints`: point_lights=march (point lights then have no epipolar frame).
IntegrandChoice chooseIntegrand(const scene::Scene& scene, int rank, int textureColumns, bool marchPoints);

// chooseIntegrand with a memory of its last answer: the factorisation costs about 5 ms (64 x 64 Jacobi SVD)
// and plan() runs on every frame of a camera drag; the answer is reused while the lights' GPU description,
// the camera, the medium and the settings are bit for bit those it was worked out for. Thread-safe.
class IntegrandChooser {
public:
    IntegrandChoice choose(const scene::Scene& scene, int rank, int textureColumns, bool marchPoints) const;

private:
    mutable std::mutex mMutex;
    mutable std::string mKey;
    mutable IntegrandChoice mChoice;
};

}  // namespace viz::minmax
