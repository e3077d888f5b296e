// minmax's GL passes: light setup, rectification, prefix sums, min-max trees and the traversal.
#include "techniques/minmax/minmax_technique.h"

#include "core/text.h"
#include "scene/ray_reach.h"

namespace viz::minmax_detail {

void MinmaxTechnique::prepareLights(const scene::Scene& scene, const FrameInput& input, std::vector<std::string>& notes) {
    const auto& lights = mView.lights().lights();
    const MinmaxSettings& s = mSettings;
    const int columns = s.columns > 0 ? s.columns : s.shadowMap;
    std::vector<LightWork> work;
    mBruteLights.clear();
    for (int i = 0; i < int(lights.size()); ++i) {
        const auto& L = lights[std::size_t(i)];
        const bool point = L.info.x == render::hd::kLightPoint && !s.marchPoints;
        const bool atEye = render::atEye(L);
        const bool epipolar = (L.info.x == render::hd::kLightSpot || L.info.x == render::hd::kLightDirectional ||
                               point) &&
                              L.info.z >= 0 && !atEye;
        if (!epipolar) {
            mBruteLights.push_back(i);
            continue;
        }
        LightWork w;
        w.gpuIndex = i;
        w.setup = minmax::setupLight({.light = &L, .camera = &scene.camera, .width = input.width,
                                      .height = input.height, .slices = s.slices,
                                      .columns = columns,
                                      .oversampling = s.sliceOversampling, .fixedFrame = s.fixedFrame});
        sliceGapNote(scene, L.info.w, input, w.setup, notes);
        // This light's GPU objects from the previous frame; the map and tree are made again when their
        // size changes (prefixSums() and the lines below check the table's and the gamma buffer's).
        const std::size_t k = work.size();
        if (k < mWork.size()) static_cast<LightTargets&>(w) = std::move(static_cast<LightTargets&>(mWork[k]));
        const int c = w.setup.frame.columns, r = w.setup.frame.slices;
        if (!w.rectified || w.rectified.size() != glm::ivec3(c, r, 1)) {
            w.rectified = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32F, .size = {c, r, 1},
                                               .levels = 1, .label = kRectified});
            w.tree = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RG32F, .size = {2 * c, r, 1},
                                          .levels = 1, .label = kTree});
            w.rectified.setFilter(GL_NEAREST, GL_NEAREST);
            w.tree.setFilter(GL_NEAREST, GL_NEAREST);
        }
        const std::size_t rowGammaBytes = sizeof(std::uint32_t) * std::size_t(sliceCount(w));
        if (w.point() && (!w.rowGamma || w.rowGamma.bytes() != rowGammaBytes))
            w.rowGamma = gl::Buffer::create({.bytes = rowGammaBytes, .label = kRowGamma});
        work.push_back(std::move(w));
    }
    mWork = std::move(work);
}

void MinmaxTechnique::sliceGapNote(const scene::Scene& scene, int light, const FrameInput& input,
                                   const minmax::Setup& setup, std::vector<std::string>& notes) const {
    const int fixed = mSettings.slices;
    const int k = std::max(1, mSettings.sliceOversampling);
    const double promised = fixed > 0 ? 1.0 : 1.0 / k;  // largest gap the setting stands for (pixels)
    if (setup.maxSliceGap <= promised * (1.0 + 1e-6)) return;
    const std::string name = light >= 0 && light < int(scene.lights.size()) ? scene.lights[std::size_t(light)].name
                                                                              : "light";
    const std::string why = fixed > 0 ? "slices=" + std::to_string(fixed) + " is too few for this image"
                                      : "the cap of " + std::to_string(minmax::kMaxSlices) +
                                            " slices is reached (slice_oversampling " + std::to_string(k) + " asks for " +
                                            viz::format("%.0f", std::ceil(setup.maxSliceGap / promised * setup.frame.slices)) + ")";
    char figure[160];
    std::snprintf(figure, sizeof figure, "%.2f px apart, so a ray may take a slice %.2f px away (promised %.2f)",
                  setup.maxSliceGap, 0.5 * setup.maxSliceGap, 0.5 * promised);
    notes.push_back("minmax, " + name + ": " + std::to_string(setup.frame.slices) + " slices at " +
                    std::to_string(input.width) + "x" + std::to_string(input.height) + " are up to " + figure +
                    ": shadow edges may shift by that much; " + why);
}

void MinmaxTechnique::setFrameUniforms(const gl::Program& p, const minmax::EpipolarFrame<float>& f) const {
    p.set("uKind", int(f.kind));
    p.set("uAxis", f.axis);
    p.set("uU", f.u);
    p.set("uV", f.v);
    p.set("uLightDistance", f.lightDistance);
    p.set("uSlices", f.slices);
    p.set("uColumns", f.columns);
    p.set("uWrap", f.wrap);
    p.set("uAlphaLo", f.alphaLo);
    p.set("uAlphaSpacing", f.alphaSpacing);
    p.set("uGammaLo", f.gammaLo);
    p.set("uGammaHi", f.gammaHi);
}

void MinmaxTechnique::measureRowGamma(LightWork& w, const scene::Scene& scene, const FrameInput& input) {
    if (!mGammaRange)
        mGammaRange = gl::Program::compile({.stages = {"minmax/gamma_range.comp"},
                                            .defines = {{"EPIPOLAR_POINT", "1"}},
                                            .label = "minmax.gamma_range"});
    w.rowGamma.clearZero();
    mGammaRange.use();
    setFrameUniforms(mGammaRange, minmax::toFloat(w.setup.frame));
    render::bindCameraRay(mGammaRange, scene.camera, input.width, input.height);
    w.rowGamma.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
    mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
    const glm::ivec3 groups = gl::groupCount({input.width, input.height, 1}, mGammaRange.workGroupSize());
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void MinmaxTechnique::rectify(LightWork& w) {
    if (!mRectify) mRectify = gl::Program::compile({.stages = {"minmax/rectify.comp"}, .label = kStageRectify});
    if (w.point() && !mRectifyPoint)
        mRectifyPoint = gl::Program::compile({.stages = {"minmax/rectify.comp"},
                                              .defines = {{"EPIPOLAR_POINT", "1"}},
                                              .label = kStageRectify});
    const gl::Program& program = w.point() ? mRectifyPoint : mRectify;
    const auto f = minmax::toFloat(w.setup.frame);
    program.use();
    setFrameUniforms(program, f);
    program.set("uLight", w.gpuIndex);
    mView.lights().bind();
    mView.shadows().bind();
    if (w.point()) w.rowGamma.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
    w.rectified.bindImage(0, GL_WRITE_ONLY);
    const glm::ivec3 groups = gl::groupCount({f.columns, f.slices, 1}, program.workGroupSize());
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void MinmaxTechnique::prefixSums(LightWork& w, const scene::Scene& scene) {
    const MinmaxSettings& s = mSettings;
    const auto& f = w.setup.frame;
    const int rank = s.rank;
    w.lowRank = minmax::lowRankIntegrand(f, w.setup.betaLo, w.setup.betaHi, scene.medium.sigma_s,
                                         scene.medium.sigma_t(), scene.medium.g, rank);
    const int texels = s.textureColumns;
    // Spot: T varies with alpha; point: every row has its own gamma range. Both need a table per slice.
    const bool perRow = f.kind != LightKind::Directional;
    const int rows = perRow ? f.slices : 1;
    const int layers = (3 * rank + 3) / 4;
    if (!w.prefix || w.prefix.size() != glm::ivec3(texels + 1, rows, layers)) {
        w.prefix = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32F,
                                        .size = {texels + 1, rows, layers}, .levels = 1, .label = kPrefixSums});
        w.prefix.setFilter(GL_LINEAR, GL_LINEAR);
        w.prefix.setWrap(GL_CLAMP_TO_EDGE);
    }
    w.prefixRows = rows;
    const int variant = (w.point() ? 1 : 0) | (mLog2Prefix ? 2 : 0) | (rank << 2);
    gl::Program& program = mPrefix[variant];
    if (!program) {
        gl::ShaderDefines defines;
        if (w.point()) defines.push_back({"EPIPOLAR_POINT", "1"});
        if (mLog2Prefix) defines.push_back({"LOG2_PASSES", "1"});
        defines.push_back({"MINMAX_RANK", std::to_string(rank)});
        program = gl::Program::compile({.stages = {"minmax/prefix.comp"}, .defines = defines, .label = "minmax.prefix"});
    }
    program.use();
    setFrameUniforms(program, minmax::toFloat(f));
    program.set("uLight", w.gpuIndex);
    program.set("uRows", rows);
    program.set("uTexels", texels);
    program.set("uSharedRow", !perRow);
    VIZ_CHECK(w.lowRank.basisGamma.size() % 4 == 0, "minmax: the gamma basis is packed four floats to a vec4");
    glProgramUniform4fv(program.id(), program.location("uGammaBasis[0]"), GLsizei(w.lowRank.basisGamma.size() / 4),
                        w.lowRank.basisGamma.data());
    mView.lights().bind();
    if (w.point()) w.rowGamma.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
    w.prefix.bindImage(0, GL_WRITE_ONLY);
    // log2 passes: one work group per row; sequential: one invocation per row.
    const int groups = mLog2Prefix ? rows : gl::groupCount({rows, 1, 1}, program.workGroupSize()).x;
    glDispatchCompute(GLuint(groups), 1, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void MinmaxTechnique::buildTree(LightWork& w, int wanted) {
    if (!mMipmap) mMipmap = gl::Program::compile({.stages = {"minmax/mipmap.comp"}, .label = kStageMipmap});
    const auto& f = w.setup.frame;
    const int levels = levelCount(w);
    mMipmap.use();
    mMipmap.set("uLeaves", f.columns);
    mMipmap.set("uSlices", f.slices);
    w.rectified.bindImage(0, GL_READ_ONLY);
    w.tree.bindImage(1, GL_READ_WRITE);
    const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    w.tree.clear(GL_RGBA, GL_FLOAT, zero);
    auto pass = [&](int level, int count) {
        mMipmap.set("uLevel", level);
        const glm::ivec3 groups = gl::groupCount({count, f.slices, 1}, mMipmap.workGroupSize());
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    };
    pass(-1, f.columns);
    w.levelsBuilt = 0;
    for (int level = levels - 1; level >= 0; --level) {
        if (wanted > 0 && w.levelsBuilt >= wanted) break;
        pass(level, 1 << level);
        ++w.levelsBuilt;
    }
}

void MinmaxTechnique::allocateTargets(int width, int height) {
    if (mAirlight && mAirlight.size().x == width && mAirlight.size().y == height) return;
    auto make = [&](GLenum format, const char* label) {
        return gl::Texture::create({.target = GL_TEXTURE_2D, .format = format, .size = {width, height, 1},
                                    .levels = 1, .label = label});
    };
    mAirlight = make(GL_RGBA32F, kAirlight);
    mVisited = make(GL_R32F, kVisited);
    mNearMask = make(GL_R32F, kNearMask);
    mRayCoords = make(GL_RGBA32F, kRayCoords);
}

const gl::Program& MinmaxTechnique::traverseProgram(const Plan& plan) {
    std::string key;
    gl::ShaderDefines defines = permutationDefines(plan, kDefines, &key);
    mFarRays = featureEnabled(plan, "FAR_RAYS");
    if (featureEnabled(plan, "INTEGRAND_SVD")) {
        // The rank is compiled in (its loops unroll and the per-rank sums stay in registers).
        defines.push_back({"MINMAX_RANK", std::to_string(mSettings.rank)});
        key += " rank=" + std::to_string(mSettings.rank);
    }
    if (key != mProgramKey || !mTraverse) {
        mTraverse = gl::Program::compile(
            {.stages = {"minmax/traverse.comp"}, .defines = defines, .label = kStageTraverse});
        mProgramKey = key;
    }
    return mTraverse;
}

void MinmaxTechnique::traverse(const gl::Program& program, const scene::Scene& scene, const FrameInput& input,
              const LightWork* work, int gpuIndex, bool writeCoords) {
    const scene::Camera& cam = scene.camera;
    const MinmaxSettings& s = mSettings;
    program.use();
    render::bindCameraRay(program, cam, input.width, input.height);
    mMedium.bind(scene.medium);
    program.set("uLinear", s.linear);
    program.set("uPieces", s.spotPieces);
    program.set("uMarchSamples", s.marchSamples);
    program.set("uVplSamples", s.vplSamples);
    if (mFarRays) {
        program.set("uFarSpan", float(scene::farSpan(scene)));
        program.set("uAxisReach", float(scene::depthOfInterest(scene)));
    }
    program.set("uEpipoleRadius", float(s.epipoleRadius));
    program.set("uWriteCoords", writeCoords);
    glm::vec4 epipoles(-1e9f);
    if (work) {
        program.set("uMode", 0);
        program.set("uLight", gpuIndex);
        setFrameUniforms(program, minmax::toFloat(work->setup.frame));
        const auto e = minmax::screenEpipoles(cam, input.width, input.height, work->setup.frame.axis);
        if (e.epipole.valid) epipoles = glm::vec4(glm::vec2(e.epipole.pixel), epipoles.z, epipoles.w);
        if (e.antiEpipole.valid) epipoles = glm::vec4(epipoles.x, epipoles.y, glm::vec2(e.antiEpipole.pixel));
        work->tree.bindUnit(render::hd::kFirstFreeTextureUnit + 1);
        if (work->point()) work->rowGamma.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
        if (mSvd && work->prefix) {
            const minmax::LowRank& lr = work->lowRank;
            program.set("uPrefixTexels", work->prefix.size().x - 1);
            program.set("uPrefixRows", work->prefixRows);
            // A point light's rows each span their own gamma range: their tables' texels do not line up.
            program.set("uBlendRows", s.blendRows && !work->point() && work->prefixRows > 1);
            program.set("uBetaLo", float(lr.betaLo));
            program.set("uBetaHi", float(lr.betaHi));
            VIZ_CHECK(lr.basisB.size() % 4 == 0, "minmax: the beta basis is packed four floats to a vec4");
            glProgramUniform4fv(program.id(), program.location("uBetaBasis[0]"), GLsizei(lr.basisB.size() / 4),
                                lr.basisB.data());
            work->prefix.bindUnit(render::hd::kFirstFreeTextureUnit + 2);
        }
    } else {
        program.set("uMode", 1);
        program.set("uLight", gpuIndex);
        program.set("uColumns", 1);
        program.set("uSlices", 1);
        program.set("uGammaHi", 1.0f);
    }
    program.set("uEpipoles", epipoles);
    mView.lights().bind();
    mView.shadows().bind();
    mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
    mAirlight.bindImage(0, GL_READ_WRITE);
    mVisited.bindImage(1, GL_READ_WRITE);
    mNearMask.bindImage(2, GL_READ_WRITE);
    mRayCoords.bindImage(3, GL_WRITE_ONLY);
    const glm::ivec3 groups = gl::groupCount({input.width, input.height, 1}, program.workGroupSize());
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                    GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace viz::minmax_detail
