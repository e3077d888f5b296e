// The minmax tests' view of a light's epipolar frame: the float frame the technique's run() builds for
// light `index` of a scene (the same GpuLights and setup, the default slice_oversampling).
#pragma once

#include "render/gpu_lights.h"
#include "scene/scene.h"
#include "techniques/minmax/epipolar_setup.h"
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

}  // namespace viz::testing
