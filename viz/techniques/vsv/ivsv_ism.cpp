// ivsv's VPLs and imperfect shadow maps: the tile layout of one ISM per VPL, the VPL upload, the point
// cloud splatted into the tiles and the push-pull that fills their holes.
#include "techniques/vsv/ivsv_technique.h"

#include "scene/ray_reach.h"
#include "scene/scene_source.h"

namespace viz::ivsv_detail {

void IvsvTechnique::layOut(int count, int cells, int tile) {
    mTilesX = int(std::ceil(std::sqrt(double(count))));
    mTilesY = (count + mTilesX - 1) / mTilesX;
    const glm::ivec3 gridSize(mTilesX * cells, mTilesY * cells, 1);
    if (!mGrid || mGrid.size() != gridSize) {
        mGrid = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32UI, .size = gridSize,
                                     .levels = 1, .label = "ivsv.grid"});
        mPong = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_RGBA32UI, .size = gridSize,
                                     .levels = 1, .label = "ivsv.grid_pong"});
        mWords = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY, .format = GL_R32UI,
                                      .size = {gridSize.x, gridSize.y, 4}, .levels = 1, .label = "ivsv.words"});
    }
    const glm::ivec3 ismSize(mTilesX * tile, mTilesY * tile, 1);
    if (!mIsm || mIsm.size() != ismSize) {
        const int levels = scanPassCount(tile) + 1;
        mIsmBits = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32UI, .size = ismSize, .levels = 1,
                                        .label = "ivsv.ism_bits"});
        mIsmRaw = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32F, .size = ismSize, .levels = 1,
                                       .label = kIsmRaw});
        mIsm = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32F, .size = ismSize, .levels = levels,
                                    .label = kIsm});
    }
    if (!mVplBuffer) {
        mVplBuffer = gl::Buffer::create({.bytes = kMaxVpls * sizeof(GpuVpl), .label = "ivsv.vpls"});
        mPick = gl::Buffer::create({.bytes = kMaxVpls * sizeof(glm::vec4), .label = "ivsv.pick"});
    }
    if (!mSplat) {
        mSplat = gl::Program::compile({.stages = {"vsv/ism_splat.comp"}, .label = "ivsv.ism_splat"});
        mPushPull = gl::Program::compile({.stages = {"vsv/ism_pushpull.comp"}, .label = "ivsv.ism_pushpull"});
        mRectifyIsm = gl::Program::compile({.stages = {"vsv/ivsv_voxelize.comp"}, .label = "ivsv.rectify"});
        mRectifyCube = gl::Program::compile(
            {.stages = {"vsv/ivsv_voxelize.comp"}, .defines = {{"CUBE", "1"}}, .label = "ivsv.rectify_cube"});
        mPack = gl::Program::compile({.stages = {"vsv/pack.comp"}, .label = "ivsv.pack"});
        mScan = gl::Program::compile({.stages = {"vsv/scan.comp"}, .label = "ivsv.scan"});
        mBilateral = gl::Program::compile({.stages = {"vsv/bilateral.comp"}, .label = "ivsv.bilateral"});
    }
}

void IvsvTechnique::uploadVpls(const scene::Scene& scene, int width, int height, int cells, int tile) {
    mGrids.clear();
    std::vector<GpuVpl> gpu;
    const vsv::CameraRays cam = vsv::cameraRays(scene.camera, width, height);
    for (int i = 0; i < int(mVpls.size()); ++i) {
        const vsv::Vpl& v = mVpls[std::size_t(i)];
        const glm::dvec3 rel = v.position - scene.camera.position;
        const vsv::EpipolarFrame f = vsv::makeFrame(rel);
        vsv::SpotCone cone;
        cone.present = true;
        cone.axis = v.normal;
        cone.outer = 0.5 * std::numbers::pi;
        const vsv::EpipolarGrid g = vsv::selectRanges(f, cam, scene::depthOfInterest(scene), cone, cells, cells, kPhiBits);
        mGrids.push_back(g);
        glm::dvec3 tx, ty;
        vsv::hemisphereFrame(v.normal, tx, ty);
        GpuVpl o{};
        o.position = glm::vec4(glm::vec3(rel), 0.0f);
        o.normal = glm::vec4(glm::vec3(v.normal), 0.0f);
        o.tangent = glm::vec4(glm::vec3(tx), 0.0f);
        o.bitangent = glm::vec4(glm::vec3(ty), 0.0f);
        o.weight = glm::vec4(glm::vec3(v.weight), float(mVplArea / std::numbers::pi));
        // The grid layout's cell (the gather takes it with vpl_kernel=cell), eye-relative like the position.
        const bool cell = glm::length(glm::cross(v.edgeU, v.edgeV)) > 0.0;
        o.cellCorner = glm::vec4(glm::vec3(v.corner - scene.camera.position), cell ? float(mVplArea) : 0.0f);
        o.cellU = glm::vec4(glm::vec3(v.edgeU), 0.0f);
        o.cellV = glm::vec4(glm::vec3(v.edgeV), 0.0f);
        o.epiB = glm::vec4(glm::vec3(f.b), float(f.D));
        o.epiU = glm::vec4(glm::vec3(f.u), 0.0f);
        o.epiV = glm::vec4(glm::vec3(f.v), 0.0f);
        o.epiAlpha = glm::vec4(float(g.alpha0), float(g.dAlpha()), 0.0f, 0.0f);
        o.epiTheta = glm::vec4(float(g.thetaCentre), float(g.thetaHalf), float(g.dTheta()), g.thetaFull ? 1.0f : 0.0f);
        o.epiPhi = glm::vec4(float(g.phi0), float(g.dPhi()), 0.0f, 0.0f);
        o.tile = glm::ivec4(tileOrigin(i, cells), tileOrigin(i, tile));
        // x: mode=naive's point light and cube (VPL i is light i); y, z: the grid reaches the epipole
        // toward / away from the VPL (the gather's EPIPOLE case).
        o.extra = glm::ivec4(i, g.epipoleToward && g.alpha0 == 0.0 ? 1 : 0,
                             g.epipoleAway && g.alpha1 >= std::numbers::pi ? 1 : 0, 0);
        gpu.push_back(o);
    }
    if (!gpu.empty()) mVplBuffer.upload(0, gpu.size() * sizeof(GpuVpl), gpu.data());
}

void IvsvTechnique::buildIsm(const scene::Scene& scene, const scene::Light& light, int points, int count, int tile, int fillLevels) {
    const std::size_t key = std::size_t(scene::geometryKeyOf(scene)) ^ (std::size_t(points) * 2654435761u);
    if (key != mPointsKey || &scene != mPointsScene) {
        mCloudWorld = vsv::samplePointCloud(scene, points, light.mesh);
        mPointsKey = key;
        mPointsScene = &scene;
        mCloud.clear();
    }
    // Uploaded eye-relative, like every position the shaders see; again when the camera moved.
    if (mCloud.empty() || mCloudEye != scene.camera.position) {
        mCloud.clear();
        for (const glm::dvec3& p : mCloudWorld) mCloud.emplace_back(glm::vec3(p - scene.camera.position), 1.0f);
        if (mCloud.empty()) mCloud.emplace_back(0.0f);
        mPoints = gl::Buffer::create(
            {.bytes = mCloud.size() * sizeof(glm::vec4), .data = mCloud.data(), .label = kPointCloud});
        mCloudEye = scene.camera.position;
    }
    const GLuint empty = 0xffffffffu;
    mIsmBits.clear(GL_RED_INTEGER, GL_UNSIGNED_INT, &empty);
    mSplat.use();
    mSplat.set("uPointCount", int(mCloudWorld.size()));
    mSplat.set("uVplCount", count);
    mSplat.set("uTileSize", tile);
    mVplBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 4);
    mPoints.bindBase(GL_SHADER_STORAGE_BUFFER, 5);
    mIsmBits.bindImage(0, GL_READ_WRITE);
    glDispatchCompute(GLuint((mCloud.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);

    // Push-pull only over the rows of tiles holding VPLs.
    const glm::ivec2 used(mTilesX * tile, mTilesY * tile);
    mPushPull.use();
    auto dispatch = [&](glm::ivec2 size) {
        mPushPull.set("uSize", size);
        const glm::ivec3 groups = gl::groupCount({size.x, size.y, 1}, mPushPull.workGroupSize());
        glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    };
    mPushPull.set("uMode", 0);
    mIsmBits.bindImage(0, GL_READ_ONLY);
    mIsm.bindImage(1, GL_READ_WRITE, 0);
    mIsm.bindImage(2, GL_READ_WRITE, 0);
    mIsmRaw.bindImage(3, GL_WRITE_ONLY);
    dispatch(used);
    const int levels = mIsm.levels();
    mPushPull.set("uMode", 1);
    for (int l = 0; l + 1 < levels; ++l) {
        mIsm.bindImage(1, GL_READ_WRITE, l);
        mIsm.bindImage(2, GL_READ_WRITE, l + 1);
        dispatch(used >> (l + 1));
    }
    mPushPull.set("uMode", 2);
    mPushPull.set("uFillLevels", fillLevels);
    for (int l = levels - 2; l >= 0; --l) {
        mPushPull.set("uLevel", l);
        mIsm.bindImage(1, GL_READ_WRITE, l);
        mIsm.bindImage(2, GL_READ_WRITE, l + 1);
        dispatch(used >> l);
    }
}

}  // namespace viz::ivsv_detail
