// ivsv's GL passes after the ISMs: rectification into epipolar grids, the voxel scan, the gather and the
// scene's other lights.
#include "techniques/vsv/ivsv_technique.h"

#include "techniques/vsv/vsv_technique.h"  // vsv_detail::kAirlight

namespace viz::ivsv_detail {

void IvsvTechnique::setRectifyCommon(const gl::Program& p, const IvsvSettings& s, int cells, int tile) const {
    p.use();
    p.set("uCells", glm::ivec3(cells, cells, kPhiBits));
    p.set("uTileSize", tile);
    p.set("uAlphaBias", float(s.alphaBias));
    p.set("uPhiBias", float(s.phiBias));
}

void IvsvTechnique::rectify(const IvsvSettings& s, int count, int cells, int tile, bool naive) {
    const GLuint zero = 0;
    mWords.clear(GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    mVplBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 4);
    mWords.bindImage(0, GL_READ_WRITE);
    const glm::ivec3 groups = gl::groupCount({kPhiBits, cells, 1}, glm::ivec3(8, 8, 1));
    if (naive) {
        mNaiveView.shadows().bind();
        setRectifyCommon(mRectifyCube, s, cells, tile);
        for (int i = 0; i < count; ++i) {
            mRectifyCube.set("uFirstVpl", i);
            glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
            glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
            vsv::packGrid(mPack, mWords, mGrid, tileOrigin(i, cells), {cells, cells, 1});
            mRectifyCube.use();
            mWords.bindImage(0, GL_READ_WRITE);
        }
    } else {
        mIsm.bindUnit(render::hd::kFirstFreeTextureUnit + 1);
        setRectifyCommon(mRectifyIsm, s, cells, tile);
        mRectifyIsm.set("uFirstVpl", 0);
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), GLuint(count));
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
        vsv::packGrid(mPack, mWords, mGrid, {0, 0}, {mTilesX * cells, mTilesY * cells, 1});
    }
}

void IvsvTechnique::scan(int count, int cells, int passLimit, bool naive) {
    const int passes = std::min(passLimit, scanPassCount(cells));
    if (naive) {
        for (int i = 0; i < count; ++i)
            mResult = vsv::scanGrid(mScan, &mGrid, &mPong, tileOrigin(i, cells), {cells, cells, 1}, cells, passes);
    } else {
        mResult = vsv::scanGrid(mScan, &mGrid, &mPong, {0, 0}, {mTilesX * cells, mTilesY * cells, 1}, cells, passes);
    }
}

void IvsvTechnique::allocateOutputs(int width, int height) {
    if (mAirlight && mAirlight.size().x == width && mAirlight.size().y == height) return;
    auto rgba = [](int w, int h, const char* label) {
        return gl::Texture::create(
            {.target = GL_TEXTURE_2D, .format = GL_RGBA32F, .size = {w, h, 1}, .levels = 1, .label = label});
    };
    mAirlight = rgba(width, height, kAirlight);
    mRaw = rgba(width, height, "ivsv.gather_raw");
    mLow = rgba((width + 1) / 2, (height + 1) / 2, "ivsv.gather_quarter");
    mVisibility = gl::Texture::create(
        {.target = GL_TEXTURE_2D, .format = GL_R32F, .size = {width, height, 1}, .levels = 1, .label = kVisibility});
}

const gl::Program& IvsvTechnique::gatherProgram(bool exact, bool interp, bool epipole, bool naive, bool deinterleave) {
    const std::string key = std::string(exact ? "E" : "F") + (interp ? "I" : "N") + (epipole ? "P" : "-") +
                            (naive ? "C" : "-") + (deinterleave ? "D" : "-");
    if (key != mGatherKey || !mGather) {
        gl::ShaderDefines defines;
        if (exact) defines.push_back({"COMBINE_EXACT", "1"});
        if (interp) defines.push_back({"INTERP", "1"});
        if (epipole) defines.push_back({"EPIPOLE", "1"});
        if (naive) defines.push_back({"CUBE", "1"});
        if (deinterleave) defines.push_back({"DEINTERLEAVE", "1"});
        mGather = gl::Program::compile({.stages = {"vsv/ivsv_gather.comp"}, .defines = defines, .label = "ivsv.gather"});
        mGatherKey = key;
    }
    return mGather;
}

void IvsvTechnique::gather(const scene::Scene& scene, const FrameInput& input, int mode, int gathered, int cells, bool naive,
            glm::ivec2 pickGl) {
    const IvsvSettings& s = mSettings;
    const scene::Camera& cam = scene.camera;
    const bool epipole = s.epipole;
    const bool deinterleave = mode == kGatherInterleaved && s.deinterleave;
    const gl::Program& program = gatherProgram(s.exactCombine, s.interp, epipole, naive, deinterleave);
    const int w = input.width, h = input.height;
    gl::Texture& target = mode == kGatherFull ? mAirlight : (mode == kGatherInterleaved ? mRaw : mLow);
    const glm::ivec2 outSize = mode == kGatherQuarter ? glm::ivec2((w + 1) / 2, (h + 1) / 2) : glm::ivec2(w, h);
    // Deinterleaved: the invocations cover the nine sub-images (pixels of one place in the 3x3 pattern)
    // side by side, each padded to whole work groups, so no group straddles two sub-images.
    const glm::ivec3 groupSize = program.workGroupSize();
    auto wholeGroups = [](int n, int g) { return (n + g - 1) / g * g; };
    const glm::ivec2 subSize{wholeGroups((w + 2) / 3, groupSize.x), wholeGroups((h + 2) / 3, groupSize.y)};
    program.use();
    program.set("uOutSize", outSize);
    if (deinterleave) program.set("uSubSize", subSize);
    render::bindCameraRay(program, cam, w, h);
    program.set("uScale", mode == kGatherQuarter ? 2 : 1);
    program.set("uCells", glm::ivec3(cells, cells, kPhiBits));
    program.set("uVplStride", mode == kGatherInterleaved ? 9 : 1);
    program.set("uPhaseShift", phaseShift(s, input));
    mMedium.bind(scene.medium);
    program.set("uChunkBits", s.chunkBits);
    program.set("uDiscScale", s.vplKernel != 0.0 ? 1.0f : 0.0f);
    program.set("uPick", pickGl);
    mVplBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 4);
    mPick.bindBase(GL_SHADER_STORAGE_BUFFER, 6);
    mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
    program.set("uTileSize", tileSize(s));
    if (epipole && naive) mNaiveView.shadows().bind();
    if (epipole && !naive) mIsm.bindUnit(render::hd::kFirstFreeTextureUnit + 1);
    mResult->bindImage(0, GL_READ_ONLY);
    target.bindImage(1, GL_READ_WRITE);
    mVisibility.bindImage(2, GL_READ_WRITE);
    const glm::ivec2 invocations = deinterleave ? 3 * subSize : outSize;
    const glm::ivec3 groups = gl::groupCount({invocations.x, invocations.y, 1}, groupSize);
    // Naive: one gather pass per VPL, accumulating; imperfect: one pass over all of them.
    const int passes = naive ? gathered : 1;
    for (int i = 0; i < passes; ++i) {
        program.set("uFirstVpl", naive ? i : 0);
        program.set("uVplCount", naive ? 1 : gathered);
        program.set("uAccumulate", i > 0 ? 1 : 0);
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                        GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
    }
    if (mode == kGatherFull) return;
    mBilateral.use();
    mBilateral.set("uSize", glm::ivec2(w, h));
    mBilateral.set("uSourceSize", outSize);
    mBilateral.set("uMode", mode == kGatherInterleaved ? 0 : 1);
    mBilateral.set("uSigma", float(s.bilateralSigma));
    target.bindImage(0, GL_READ_ONLY);
    mAirlight.bindImage(1, GL_WRITE_ONLY);
    const glm::ivec3 g2 = gl::groupCount({w, h, 1}, mBilateral.workGroupSize());
    glDispatchCompute(GLuint(g2.x), GLuint(g2.y), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void IvsvTechnique::addOtherLights(const FrameInput& input) {
    mOtherLightsScene = withoutAreaLights(*input.scene);
    if (!mVsv) mVsv = makeVsvTechnique();
    FrameInput in;
    in.scene = &mOtherLightsScene;
    in.width = input.width;
    in.height = input.height;
    // The same grid as the VPLs' on every axis (vsv rounds phi up to whole 32-bit words itself); vsv's
    // one-size `voxels` (32 to 1024) cannot say every size ivsv accepts (16 to 512): 16 once failed.
    const double v = double(mSettings.voxels);
    setRunSettings(in, completeSettings(*mVsv, {{"voxels_alpha", v}, {"voxels_theta", v}, {"voxels_phi", v}}));
    in.stopAfterStage = 4;  // vsv.gather: L_air exists, no compose needed
    in.readBack = false;    // the add reads the inner L_air's texture
    in.timer = input.timer;  // the caller's clock, if it gave one, times the inner stages too
    mAdder.add(mAirlight, mVsv->run(in), vsv_detail::kAirlight);
}

}  // namespace viz::ivsv_detail
