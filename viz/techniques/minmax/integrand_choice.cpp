#include "techniques/minmax/integrand_choice.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/gpu_lights.h"
#include "techniques/minmax/epipolar_setup.h"
#include "techniques/minmax/low_rank.h"

namespace viz::minmax {

namespace {

// The lights with an epipolar frame, as the run's GpuLights will describe them.
std::vector<render::GpuLightCpu> epipolarLights(const scene::Scene& scene, bool marchPoints) {
    std::vector<render::GpuLightCpu> out;
    for (const render::GpuLightCpu& L : render::describeLights(scene, scene.camera.position, 1).lights) {
        const bool point = L.info.x == render::hd::kLightPoint && !marchPoints;
        if (L.info.x == render::hd::kLightSpot || L.info.x == render::hd::kLightDirectional || point)
            out.push_back(L);
    }
    return out;
}

std::string percent(double fraction) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2g %%", 100.0 * fraction);
    return text;
}

// chooseIntegrand over the epipolar lights already described.
IntegrandChoice chooseFor(const scene::Scene& scene, const std::vector<render::GpuLightCpu>& lights, int rank,
                          int textureColumns) {
    IntegrandChoice c;
    const std::string r = "rank-" + std::to_string(rank);
    if (scene.medium.sigma_s == 0.0) {
        c.why = "integrand=auto: analytic (sigma_s = 0: nothing scatters, nothing to factorise)";
        return c;
    }
    if (lights.empty()) {
        c.why = "integrand=auto: analytic (no spot, directional or point light to factorise)";
        return c;
    }
    // Suns alone: a sun's lit run is a closed form, exact, and its traverse costs less than svd's table
    // lookups (README "Integrands", auto: 640x480, traverse 2x, the whole run 1.26x), so there is nothing for
    // the tables to buy.
    if (std::all_of(lights.begin(), lights.end(),
                    [](const render::GpuLightCpu& L) { return L.info.x == render::hd::kLightDirectional; })) {
        c.why = "integrand=auto: analytic (suns only: each lit run is a closed form, exact and cheaper than "
                "svd's table lookups)";
        return c;
    }
    // The frame depends on the screen's directions, not its resolution: a small image of the camera's
    // aspect (4:3 without one) gives the beta range the run's frame will have.
    const double aspect = scene.camera.aspectRatio > 0.0 ? scene.camera.aspectRatio : 4.0 / 3.0;
    const int width = 64, height = std::max(1, int(std::lround(64.0 / aspect)));
    for (const render::GpuLightCpu& L : lights) {
        const Setup setup = setupLight({.light = &L, .camera = &scene.camera, .width = width, .height = height,
                                        .slices = 0, .columns = 64, .oversampling = 1});
        const LowRank lr = lowRankIntegrand(setup.frame, setup.betaLo, setup.betaHi, scene.medium.sigma_s,
                                            scene.medium.sigma_t(), scene.medium.g, rank);
        const double error = rowIntegralError(setup.frame, lr, scene.medium.sigma_s, scene.medium.sigma_t(),
                                              scene.medium.g, textureColumns);
        // NaN (a degenerate frame) counts as the worst.
        if (!(error <= c.worstError)) {
            c.worstError = error;
            c.worstLight = scene.lights[std::size_t(L.info.w)].name;
        }
    }
    const std::string measured = r + " SVD with " + std::to_string(textureColumns) + "-texel tables is " +
                                 (std::isfinite(c.worstError) ? percent(c.worstError) : std::string("wholly")) +
                                 " off on the fully lit rays of light '" + c.worstLight + "' (limit " +
                                 percent(kAutoSvdLimit) + ")";
    c.svd = c.worstError <= kAutoSvdLimit;
    c.why = c.svd ? "integrand=auto: svd, the faster one (prefix-sum lookups per lit run); the " + measured
                  : "integrand=auto: analytic, the accurate one: the " + measured;
    return c;
}

}  // namespace

IntegrandChoice chooseIntegrand(const scene::Scene& scene, int rank, int textureColumns, bool marchPoints) {
    return chooseFor(scene, epipolarLights(scene, marchPoints), rank, textureColumns);
}

IntegrandChoice IntegrandChooser::choose(const scene::Scene& scene, int rank, int textureColumns,
                                         bool marchPoints) const {
    // Everything chooseIntegrand reads, byte for byte: the epipolar lights (all 4-byte fields, no padding),
    // the camera, the medium, the settings.
    std::string key;
    auto append = [&key](const void* data, std::size_t bytes) { key.append(static_cast<const char*>(data), bytes); };
    const std::vector<render::GpuLightCpu> lights = epipolarLights(scene, marchPoints);
    for (const render::GpuLightCpu& L : lights) append(&L, sizeof L);
    const scene::Camera& c = scene.camera;
    for (double v : {c.position.x, c.position.y, c.position.z, c.forward.x, c.forward.y, c.forward.z, c.up.x, c.up.y,
                     c.up.z, c.yfov, c.aspectRatio, scene.medium.sigma_s, scene.medium.sigma_t(), scene.medium.g,
                     double(rank), double(textureColumns), double(marchPoints)})
        append(&v, sizeof v);
    const std::lock_guard lock(mMutex);
    if (key != mKey) {
        mChoice = chooseFor(scene, lights, rank, textureColumns);
        mKey = std::move(key);
    }
    return mChoice;
}

}  // namespace viz::minmax
