// vsv's GL passes: the per-light epipolar voxel grids, their voxelization and scan, the gather and the
// scene's area lights (left to ivsv).
#include "techniques/vsv/vsv_technique.h"

#include "techniques/vsv/ivsv_technique.h"  // ivsv_detail::kAirlight

namespace viz::vsv_detail {

void VsvTechnique::allocate(const GridSize& size, int width, int height, int lightCount) {
    const int layers = (size.phi + 127) / 128;
    const glm::ivec3 grid(size.alpha, size.theta, layers);
    if (mGridSize != grid || int(mGrid.size()) != lightCount) {
        mGrid.clear();
        mPong.clear();
        mOccluder.clear();
        for (int i = 0; i < lightCount; ++i) {
            mGrid.push_back(gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32UI,
                                                 .size = grid, .levels = 1, .label = "vsv.grid"}));
            mPong.push_back(gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32UI,
                                                 .size = grid, .levels = 1, .label = "vsv.grid_pong"}));
            mOccluder.push_back(gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32F,
                                                     .size = {size.phi, size.theta, 1}, .levels = 1,
                                                     .label = kOccluder}));
        }
        mWords = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_R32UI,
                                      .size = {size.alpha, size.theta, 4 * layers}, .levels = 1,
                                      .label = "vsv.words"});
        mResult.assign(std::size_t(lightCount), nullptr);
        mGridSize = grid;
    }
    if (!mAirlight || mAirlight.size().x != width || mAirlight.size().y != height) {
        mAirlight = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RGBA32F, .size = {width, height, 1},
                                         .levels = 1, .label = kAirlight});
        mVisibility = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RGBA32F,
                                           .size = {width, height, 1}, .levels = 1, .label = kVisibility});
    }
    if (!mVoxelize) {
        mVoxelize = gl::Program::compile({.stages = {"vsv/voxelize.comp"}, .label = "vsv.voxelize"});
        mPack = gl::Program::compile({.stages = {"vsv/pack.comp"}, .label = "vsv.pack"});
        mScan = gl::Program::compile({.stages = {"vsv/scan.comp"}, .label = "vsv.scan"});
    }
}

void VsvTechnique::addAreaLights(const FrameInput& input) {
    mAreaLightsScene = onlyAreaLights(*input.scene);
    if (!mIvsv) mIvsv = makeIvsvTechnique();
    FrameInput in;
    in.scene = &mAreaLightsScene;
    in.width = input.width;
    in.height = input.height;
    // The inner ivsv's VPLs take vsv's vpl_kernel, as the surface term's do.
    setRunSettings(in, completeSettings(*mIvsv, {{"voxels", std::min(512.0, double(mSettings.voxels))},
                                                 {"vpl_kernel", input.settings.at("vpl_kernel")}}));
    in.stopAfterStage = 5;  // ivsv.gather: L_air exists, no compose needed
    in.readBack = false;    // the add reads the inner L_air's texture
    in.timer = input.timer;  // the caller's clock, if it gave one, times the inner stages too
    mAdder.add(mAirlight, mIvsv->run(in), ivsv_detail::kAirlight);
}

int VsvTechnique::gpuLightIndex(int sceneLight) const {
    const auto& gpu = mView.lights().lights();
    for (int i = 0; i < int(gpu.size()); ++i)
        if (gpu[std::size_t(i)].info.w == sceneLight) return i;
    VIZ_CHECK(false, "scene light without a GPU light");
    return -1;
}

void VsvTechnique::setEpipolar(const gl::Program& program, const vsv::EpipolarFrame& f, const vsv::EpipolarGrid& g) {
    program.set("uEpiB", glm::vec3(f.b));
    program.set("uEpiU", glm::vec3(f.u));
    program.set("uEpiV", glm::vec3(f.v));
    program.set("uEpiD", float(f.D));
    program.set("uEpiCells", glm::ivec3(g.nAlpha, g.nTheta, g.nPhi));
    program.set("uEpiAlpha", glm::vec2(float(g.alpha0), float(g.dAlpha())));
    program.set("uEpiTheta", glm::vec3(float(g.thetaCentre), float(g.thetaHalf), float(g.dTheta())));
    program.set("uEpiPhi", glm::vec2(float(g.phi0), float(g.dPhi())));
    program.set("uEpiThetaFull", g.thetaFull ? 1 : 0);
}

void VsvTechnique::voxelize(const scene::Scene& scene, const VsvSettings& s, int sceneLight, const vsv::EpipolarGrid& g, int slot) {
    const vsv::EpipolarFrame f = vsv::frameForLight(scene, scene.lights[std::size_t(sceneLight)]);
    const GLuint zero = 0;
    mWords.clear(GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    mView.lights().bind();
    mView.shadows().bind();
    mVoxelize.use();
    setEpipolar(mVoxelize, f, g);
    mVoxelize.set("uLight", gpuLightIndex(sceneLight));
    mVoxelize.set("uAlphaBias", float(s.alphaBias));
    mVoxelize.set("uPhiBias", float(s.phiBias));
    mWords.bindImage(0, GL_READ_WRITE);
    mOccluder[std::size_t(slot)].bindImage(1, GL_WRITE_ONLY);
    glm::ivec3 groups = gl::groupCount({g.nPhi, g.nTheta, 1}, mVoxelize.workGroupSize());
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    const gl::Texture& grid = mGrid[std::size_t(slot)];
    vsv::packGrid(mPack, mWords, grid, glm::ivec2(0), grid.size());
    mResult[std::size_t(slot)] = &grid;
}

void VsvTechnique::scan(int slot, const GridSize& size, int passLimit) {
    const gl::Texture& grid = mGrid[std::size_t(slot)];
    const int passes = std::min(passLimit, scanPassCount(size.alpha));
    mResult[std::size_t(slot)] = vsv::scanGrid(mScan, &grid, &mPong[std::size_t(slot)], glm::ivec2(0), grid.size(), 0, passes);
}

const gl::Program& VsvTechnique::gatherProgram(const Plan& plan) {
    std::string key;
    const gl::ShaderDefines defines = permutationDefines(plan, kDefines, &key);
    if (key != mGatherKey || !mGather) {
        mGather = gl::Program::compile({.stages = {"vsv/gather.comp"}, .defines = defines, .label = "vsv.gather"});
        mGatherKey = key;
    }
    return mGather;
}

void VsvTechnique::gather(const gl::Program& program, const scene::Scene& scene, const FrameInput& input, int sceneLight,
            const vsv::EpipolarGrid& g, int slot) {
    const scene::Camera& cam = scene.camera;
    const vsv::EpipolarFrame f = vsv::frameForLight(scene, scene.lights[std::size_t(sceneLight)]);
    program.use();
    setEpipolar(program, f, g);
    render::bindCameraRay(program, cam, input.width, input.height);
    program.set("uLight", gpuLightIndex(sceneLight));
    mMedium.bind(scene.medium);
    program.set("uRunBins", mSettings.runBins);
    program.set("uAccumulate", slot > 0 ? 1 : 0);
    program.set("uEpipoleToward", g.epipoleToward && g.alpha0 == 0.0 ? 1 : 0);
    program.set("uEpipoleAway", g.epipoleAway && g.alpha1 >= 3.141592653589793 ? 1 : 0);
    program.set("uDirectBins", float(mSettings.directBins));
    program.set("uDirectSegments", mSettings.directSegments);
    program.set("uEpipoleRule", mSettings.epipole);
    program.set("uZfar", float(cam.zfar));
    mView.lights().bind();
    mView.shadows().bind();
    mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
    mResult[std::size_t(slot)]->bindImage(0, GL_READ_ONLY);
    mAirlight.bindImage(1, GL_READ_WRITE);
    mVisibility.bindImage(2, GL_WRITE_ONLY);
    const glm::ivec3 groups = gl::groupCount({input.width, input.height, 1}, program.workGroupSize());
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace viz::vsv_detail
