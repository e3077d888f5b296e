// The minmax tests' view of a light's epipolar frame: the float frame the technique's run() builds for
// light `index` of a scene (the same GpuLights and setup, the default slice_oversampling), and the CPU
// mirror of one pixel of a run.
#pragma once

#include <string>
#include <vector>

#include "render/gpu_lights.h"
#include "scene/scene.h"
#include "technique_test_util.h"
#include "techniques/minmax/epipolar_setup.h"
#include "techniques/minmax/pixel_mirror.h"
#include "techniques/registry.h"

namespace viz::testing {

inline minmax::EpipolarFrame<float> minmaxFrame(const scene::Scene& scene, int index, int w, int h, int columns,
                                                render::GpuLightCpu* light = nullptr) {
    const render::GpuLights lights(scene, scene.camera.position, 4);
    const auto& L = lights.lights()[std::size_t(index)];
    if (light) *light = L;
    auto technique = makeTechnique("minmax");
    const int oversampling = int(completeSettings(*technique, {}).at("slice_oversampling"));
    return minmax::toFloat(minmax::setupLight({.light = &L, .camera = &scene.camera, .width = w, .height = h,
                                               .slices = 0, .columns = columns, .oversampling = oversampling})
                               .frame);
}

// The CPU mirror (pixel_mirror.h) of pixel (x, y) (row 0 at the top) of a minmax run of light 0 whose
// tree and ray coordinates were read back (keep "minmax.tree" and "minmax.ray_coords"); f and L from
// minmaxFrame.
inline minmax::MirrorResult mirrorPixel(const scene::Scene& scene, const FrameOutput& out,
                                        const minmax::EpipolarFrame<float>& f, const render::GpuLightCpu& L, int w,
                                        int h, int x, int y) {
    const Intermediate *tree = nullptr, *coords = nullptr;
    for (const Intermediate& i : out.intermediates) {
        if (i.id == "minmax.tree") tree = &i;
        if (i.id == "minmax.ray_coords") coords = &i;
    }
    minmax::MirrorLight ml;
    ml.kind = f.kind;
    ml.position = glm::vec3(L.position);
    ml.direction = glm::vec3(L.direction);
    ml.radiant = glm::vec3(L.radiant);
    ml.spotScale = L.spot.x;
    ml.spotOffset = L.spot.y;
    ml.spotCosOuter = L.spot.w;
    const minmax::MirrorMedium medium{float(scene.medium.sigma_s), float(scene.medium.sigma_t()), float(scene.medium.g)};
    const glm::vec3 ray = shaderPixelRay(scene.camera, w, h, x, y);  // traverse.comp's
    // The tree texture's GL row `row` is image row height - 1 - row.
    const int row = int(coords->image->at(x, y, 0));
    const int imageRow = tree->image->height - 1 - row;
    std::vector<glm::vec2> nodes(std::size_t(2 * f.columns));
    for (int k = 0; k < 2 * f.columns; ++k)
        nodes[std::size_t(k)] = {tree->image->at(k, imageRow, 0), tree->image->at(k, imageRow, 1)};
    return minmax::integratePixel(f, ml, medium, ray, coords->image->at(x, y, 1), coords->image->at(x, y, 2),
                                  coords->image->at(x, y, 3), nodes);
}

}  // namespace viz::testing
