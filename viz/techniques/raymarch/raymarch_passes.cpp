#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "core/blue_noise.h"
#include "render/camera_ray.h"
#include "render/host_device.h"
#include "scene/camera.h"
#include "scene/ray_reach.h"
#include "techniques/raymarch/raymarch_technique.h"

namespace viz::raymarch_detail {

void RaymarchTechnique::allocateTargets(int width, int height) {
    if (mAirlight && mAirlight.size().x == width && mAirlight.size().y == height) return;
    mAirlight = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RGBA32F, .size = {width, height, 1},
                                     .levels = 1, .label = kAirlight});
    mLitFraction = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32F, .size = {width, height, 1},
                                        .levels = 1, .label = kLitFraction});
}

const gl::Program& RaymarchTechnique::marchProgram(const Plan& plan) {
    std::string key;
    const gl::ShaderDefines defines = permutationDefines(plan, kDefines, &key);
    // One program per permutation, kept: switching settings back and forth never recompiles (and a
    // timing never includes a compile after the warm-up).
    auto it = mMarchPrograms.find(key);
    if (it == mMarchPrograms.end())
        it = mMarchPrograms
                 .emplace(key, gl::Program::compile({.stages = {"raymarch/march.comp"},
                                                     .defines = defines,
                                                     .label = "raymarch.march"}))
                 .first;
    return it->second;
}

void RaymarchTechnique::march(const gl::Program& program, const Plan& plan, const scene::Scene& scene,
                              const FrameInput& input) {
    const scene::Camera& cam = scene.camera;
    const MarchSettings& s = mSettings;
    program.use();
    render::bindCameraRay(program, cam, input.width, input.height);
    program.set("uSamples", s.samples);
    program.set("uLightCount", mView.lights().count());
    if (featureEnabled(plan, "FAR_RAYS")) program.set("uFarSpan", float(scene::farSpan(scene)));
    mMedium.bind(scene.medium);
    // jitter_time=per-frame: frame f draws new offsets (white: the seed moves by a large odd step; blue:
    // each pixel's offset moves by f times the golden ratio, modulo 1, a low-discrepancy walk in time
    // that keeps every frame's offsets a blue-noise pattern).
    const unsigned frame = s.jitterPerFrame ? unsigned(std::max(0, input.frame)) : 0u;
    program.set("uSeed", s.seed + frame * 0x9E3779B1u);
    program.set("uBlueShift", float(std::fmod(double(frame) * 0.6180339887498949, 1.0)));
    if (s.jitter == Jitter::Blue) blueNoiseTexture().bindUnit(render::hd::kFirstFreeTextureUnit + 1);
    mView.lights().bind();
    mView.shadows().bind();
    mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
    mAirlight.bindImage(0, GL_READ_WRITE);
    mLitFraction.bindImage(1, GL_READ_WRITE);
    const glm::ivec3 groups = gl::groupCount({input.width, input.height, 1}, program.workGroupSize());
    const std::int64_t pairs = std::int64_t(mView.lights().count()) * std::int64_t(s.samples);
    const std::int64_t chunk = pairsPerDispatch(s);
    for (std::int64_t begin = 0; begin == 0 || begin < pairs; begin += chunk) {
        const std::int64_t end = std::min(pairs, begin + chunk);
        program.set("uPairBegin", int(begin));
        program.set("uPairEnd", int(end));
        program.set("uFirst", begin == 0);
        program.set("uLast", end >= pairs);
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
        // The next dispatch reads what this one stored.
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    }
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

const gl::Texture& RaymarchTechnique::blueNoiseTexture() {
    if (!mBlueNoise) {
        const std::vector<float> values = blueNoise(kBlueNoiseSize);
        mBlueNoise = gl::Texture::create(
            {.format = GL_R32F, .size = {kBlueNoiseSize, kBlueNoiseSize, 1}, .label = "raymarch.blue_noise"});
        mBlueNoise.upload(GL_RED, GL_FLOAT, values.data());
    }
    return mBlueNoise;
}

}  // namespace viz::raymarch_detail
