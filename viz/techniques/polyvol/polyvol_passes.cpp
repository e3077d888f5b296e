// polyvol's GL passes: targets, the lookup table, the light volumes' meshes and their rasterisation, the
// wireframe, the resolve near the light and the final clamp.
#include "techniques/polyvol/polyvol_technique.h"

#include <list>

namespace viz::polyvol_detail {

void PolyvolTechnique::allocateTargets(int width, int height) {
    if (mTotal && mTotal.size().x == width && mTotal.size().y == height) return;
    auto make = [&](GLenum format, const char* label) {
        return gl::Texture::create(
            {.target = GL_TEXTURE_2D, .format = format, .size = {width, height, 1}, .levels = 1, .label = label});
    };
    mTotal = make(GL_RGBA32F, kTotal);
    mPositive = make(GL_RGBA32F, kPositive);
    mNegative = make(GL_RGBA32F, kNegative);
    mCrossings = make(GL_RGBA32F, kCrossings);
    mAirlight = make(GL_RGBA32F, "polyvol.airlight");
    mFramebuffer = gl::Framebuffer::create("polyvol.volume_fbo");
    mFramebuffer.attachColour(0, mTotal);
    mFramebuffer.attachColour(1, mPositive);
    mFramebuffer.attachColour(2, mNegative);
    mFramebuffer.attachColour(3, mCrossings);
    mFramebuffer.checkComplete();
}

void PolyvolTechnique::ensureLut(double g) {
    if (mLut && mLutG == g) return;
    // Built once per process and g (the table depends on nothing else), then uploaded per technique. The
    // last kLutCacheSize tables stay, most recently used first: a user dragging g does not grow it without
    // bound (each table is kLutWidth x kLutHeight x 3 floats).
    struct Cached {
        double g;
        polyvol::AirlightLut table;
        double ms;
    };
    constexpr std::size_t kLutCacheSize = 4;
    static std::list<Cached> cache;
    auto it = std::find_if(cache.begin(), cache.end(), [g](const Cached& c) { return c.g == g; });
    if (it == cache.end()) {
        const auto start = std::chrono::steady_clock::now();
        polyvol::AirlightLut built = polyvol::buildAirlightLut(g, kLutWidth, kLutHeight);
        const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        cache.push_front({g, std::move(built), ms});
        if (cache.size() > kLutCacheSize) cache.pop_back();
    } else {
        cache.splice(cache.begin(), cache, it);
    }
    it = cache.begin();
    const polyvol::AirlightLut& table = it->table;
    mLutMs = it->ms;
    mLut = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RGB32F, .size = {kLutWidth, kLutHeight, 1},
                                .levels = 1, .label = kLut});
    mLut.upload(GL_RGB, GL_FLOAT, table.texels.data());
    mLut.setFilter(GL_NEAREST, GL_NEAREST);  // read with texelFetch, interpolated in the shader
    mLut.setWrap(GL_CLAMP_TO_EDGE);
    mLutG = g;
}

const gl::Program& PolyvolTechnique::volumeProgram(const Plan& plan) {
    std::string key;
    const gl::ShaderDefines defines = permutationDefines(plan, kDefines, &key);
    mDefines = defines;
    if (key != mProgramKey || !mProgram) {
        mProgram = gl::Program::compile({.stages = {"polyvol/volume.vert", "polyvol/volume.frag"},
                                         .defines = defines,
                                         .label = "polyvol.volume"});
        gl::ShaderDefines wireDefines = defines;
        wireDefines.push_back({"WIRE_CLIP", "1"});
        mWireProgram = gl::Program::compile({.stages = {"polyvol/volume.vert", "polyvol/wire.frag"},
                                             .defines = wireDefines,
                                             .label = "polyvol.wire"});
        mProgramKey = key;
    }
    return mProgram;
}

const gl::Buffer& PolyvolTechnique::extraKeys(ExtraKind kind, int size, int stride, std::int64_t& triangles) {
    Extra& e = mExtras[{int(kind), size, stride}];
    if (!e.buffer) {
        const bool cube = kind == ExtraKind::Seams;
        // A 2D grid's closure walks the border of the key grid (the adaptive one's virtual row and
        // column N included); a cube's seams join the faces' texels 0..N - 1.
        const std::vector<std::uint32_t> keys = cube ? polyvol::cubeSeams(size, stride) : polyvol::gridClosure(stride);
        e.buffer = gl::Buffer::create({.bytes = keys.size() * sizeof(std::uint32_t),
                                       .data = keys.data(),
                                       .flags = 0,
                                       .label = cube ? "polyvol.cube_seams" : "polyvol.grid_closure"});
        e.triangles = std::int64_t(keys.size() / 3);
    }
    triangles = e.triangles;
    return e.buffer;
}

polyvol::VolumeGrid PolyvolTechnique::describe(const render::GpuLightCpu& L, int index, int n, double zfar, float cookieMask) const {
    polyvol::VolumeGrid v;
    v.lightIndex = index;
    v.layer = L.info.z;
    v.mapSize = n;
    v.keyStride = n;
    v.cookieMask = cookieMask;
    v.range = L.shadow.y - L.shadow.x;
    const glm::dvec3 pos(L.position);
    if (L.info.x == render::hd::kLightPoint || L.info.x == render::hd::kLightVpl) {
        v.mode = kModeCube;
        v.faces = 6;
        v.vplCube = L.info.x == render::hd::kLightVpl;
        if (v.vplCube) v.mapSize = v.keyStride = mView.shadows().vplSize();
        v.noHit = float((glm::length(pos) + zfar) * 1.01);
        return v;
    }
    const glm::dmat4 inv = glm::inverse(glm::dmat4(L.shadowMatrix));
    auto unproject = [&](double x, double y, double z) {
        const glm::dvec4 q = inv * glm::dvec4(x, y, z, 1.0);
        return glm::dvec3(q) / q.w;
    };
    if (L.info.x == render::hd::kLightSpot) {
        v.mode = kModeSpot;
        const glm::dvec3 axis(L.direction);
        auto plane = [&](double x, double y) {
            const glm::dvec3 d = unproject(x, y, 0.0) - pos;
            return d / glm::dot(d, axis);
        };
        const glm::dvec3 o = plane(0, 0);
        v.planeOrigin = glm::vec3(o);
        v.planeX = glm::vec3(plane(1, 0) - o);
        v.planeY = glm::vec3(plane(0, 1) - o);
        v.noHit = float((glm::length(pos) + zfar) * 1.01);
        return v;
    }
    v.mode = kModeDirectional;
    const glm::dvec3 o = unproject(0, 0, -1);
    const glm::dvec3 x = unproject(1, 0, -1) - o, y = unproject(0, 1, -1) - o;
    v.planeOrigin = glm::vec3(o), v.planeX = glm::vec3(x), v.planeY = glm::vec3(y);
    // Every point the camera can see is within zfar of the eye (the origin): the border ring is
    // pushed out far enough to cover them, empty texels reach past them, the cap lies behind them.
    const double half = std::min(glm::length(x), glm::length(y));
    const double reach = glm::length(o) + zfar;
    v.skirt = float(1.0 + (reach + half) / half);
    const double margin = 0.01 * (reach + half);
    v.noHit = float(std::max(double(L.shadow.y), zfar) + margin);
    v.capDepth = float(std::min(double(L.shadow.x), -zfar) - margin);
    return v;
}

std::int64_t PolyvolTechnique::drawVolumes(const scene::Scene& scene, const FrameInput& input, const Plan& plan) {
    const PolyvolSettings& s = mSettings;
    const scene::Camera& cam = scene.camera;
    const gl::Program& program = volumeProgram(plan);
    const int n = mView.shadows().size();
    // wireframe=3: the mesh from an orbit camera of its own, over the scene, the camera frustum and
    // the lights (render::MeshView); set up before the volume pass's state.
    if (mWireMode == 3)
        mMeshView.begin(scene, mView.gpuScene(),
                        render::orbitOf(input.controls), input.width, input.height);
    // Each light's ball radius, before the volume pass's state: nearRadius runs a compute pass.
    mNearRadii.clear();
    for (const render::GpuLightCpu& L : mView.lights().lights())
        mNearRadii.push_back(L.info.z < 0 || s.crackCheck ? 0.0f : nearRadius(L, cam, input.height));
    program.use();
    program.set("uViewProj", render::eyeRelativeViewProjection(cam, input.width, input.height));
    render::bindCameraRay(program, cam, input.width, input.height);
    program.set("uNear", float(cam.znear));
    mMedium.bind(scene.medium);
    program.set("uSpotPieces", s.spotPieces);
    program.set("uConstant", s.crackCheck ? 1 : 0);
    program.set("uOriginAtSurface", s.originAtSurface ? 1 : 0);
    mView.lights().bind();
    mView.shadows().bind();
    mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
    if (mLut) mLut.bindUnit(render::hd::kFirstFreeTextureUnit + 1);
    if (mVao.id() == 0) mVao = gl::VertexArray::create("polyvol.vao");
    mVao.bind();
    mFramebuffer.bind();
    glViewport(0, 0, input.width, input.height);
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDisable(GL_CULL_FACE);
    // Faces between the eye and the near plane must still count (ours: Billeter Sec. 5 disables the depth
    // test and clamps each fragment to the depth buffer, which volume.frag does, but is silent on the
    // near plane).
    glEnable(GL_DEPTH_CLAMP);
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    const std::int64_t limit = s.drawTriangles;
    const bool adaptiveWanted = featureEnabled(plan, "ADAPTIVE");
    const bool adaptiveCubes = featureEnabled(plan, "ADAPTIVE_CUBES");
    const int wire = mWireMode;
    mWireDrawn = false;
    if (wire) {
        if (!mWire || mWire.size().x != input.width || mWire.size().y != input.height) {
            mWire = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_RGBA8,
                                         .size = {input.width, input.height, 1}, .levels = 1,
                                         .label = kMesh});
            mWireFramebuffer = gl::Framebuffer::create("polyvol.wire_fbo");
            mWireFramebuffer.attachColour(0, mWire);
            mWireFramebuffer.checkComplete();
        }
        mWire.clear(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    }
    std::int64_t drawn = 0;
    mAdaptiveOverflow = false;
    const auto& lights = mView.lights().lights();
    // The refinement every adaptive grid of this run takes (the marks view shows the same).
    mMarkMeasure = s.edgeMeasure;
    mMarkThreshold = s.threshold;
    mMarkStopLevel = int(substepLimit(input, kVolumeIndex));
    for (int i = 0; i < int(lights.size()); ++i) {
        const render::GpuLightCpu& L = lights[std::size_t(i)];
        if (L.info.z < 0) continue;
        polyvol::VolumeGrid grid = describe(L, i, n, cam.zfar, float(s.cookieMask));
        const bool cube = grid.mode == kModeCube;
        const bool adaptive = cube ? adaptiveCubes : adaptiveWanted;
        // The crack detector counts crossings of the whole mesh: no ball there.
        const float radius = mNearRadii[std::size_t(i)];
        program.set("uNearRadius", radius);
        std::int64_t extraTriangles = 0;
        if (adaptive) {
            // Compute passes in between: the draw state is set again afterwards.
            grid.keyStride = grid.mapSize + 1;
            // 2D grids and cubes each keep their own buffers, so a scene with both kinds of light does not
            // reallocate them light after light.
            polyvol::AdaptiveTessellation& tess = cube ? mTessCube : mTess;
            tess.build(grid, mMarkMeasure, mMarkThreshold, mMarkStopLevel, mDefines, mProgramKey);
            mShownTess = &tess;
            (cube ? mCubeAdaptiveLight : mFlatAdaptiveLight) = i;
            mAdaptiveLights.push_back(i);
            mAdaptiveOverflow = mAdaptiveOverflow || tess.overflowed();
            mView.lights().bind();
            mView.shadows().bind();
            mFramebuffer.bind();
            mVao.bind();
            program.use();
            setGridUniforms(program, grid);
            program.set("uGridRows", 0);
            tess.keys().bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
            tess.counters().bind(GL_DRAW_INDIRECT_BUFFER);
            glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(polyvol::AdaptiveTessellation::drawOffset()));
            drawn += tess.triangles();
            const gl::Buffer& closure = extraKeys(cube ? ExtraKind::Seams : ExtraKind::Closure, grid.mapSize,
                                                  grid.keyStride, extraTriangles);
            closure.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
            glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * extraTriangles));
            drawn += extraTriangles;
            if (wire) drawWire(input, L, grid, closure, 0, extraTriangles, extraTriangles, &tess);
            if (s.originAtSurface || radius > 0.0f) resolve(input, i, radius);
            continue;
        }
        const std::int64_t gridTriangles = polyvol::gridTriangleCount(grid.mapSize, grid.faces);
        const gl::Buffer& keys = extraKeys(cube ? ExtraKind::Seams : ExtraKind::Closure, grid.mapSize,
                                           grid.mapSize, extraTriangles);
        setGridUniforms(program, grid);
        std::int64_t count = gridTriangles + extraTriangles;
        if (limit > 0) count = std::min(count, limit);
        drawMesh(program, grid, keys, gridTriangles, extraTriangles, count);
        drawn += count;
        if (wire) drawWire(input, L, grid, keys, gridTriangles, extraTriangles, count, nullptr);
        if (s.originAtSurface || radius > 0.0f) resolve(input, i, radius);
    }
    glDisable(GL_DEPTH_CLAMP);
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    gl::Framebuffer::bindDefault();
    return drawn;
}

void PolyvolTechnique::drawMesh(const gl::Program& program, const polyvol::VolumeGrid& grid, const gl::Buffer& keys,
                                std::int64_t gridTriangles, std::int64_t extraTriangles, std::int64_t count) {
    const int n = grid.mapSize;
    // Uploaded once per grid size (a scene's 2D maps and VPL cubes differ): lights of both kinds in one
    // frame only switch the binding.
    gl::Buffer& rowIndices = mRowIndices[n];
    if (!rowIndices) {
        // Quad i of a row: (00, 10, 11) and (00, 11, 01) with texel (i + di, j + dj) as vertex i + di + n dj,
        // counter-clockwise in the map's ndc, i.e. seen from the light.
        std::vector<std::uint32_t> indices;
        indices.reserve(6 * std::size_t(n - 1));
        for (std::uint32_t i = 0; i + 1 < std::uint32_t(n); ++i) {
            const std::uint32_t v00 = i, v10 = i + 1, v01 = i + std::uint32_t(n), v11 = i + 1 + std::uint32_t(n);
            indices.insert(indices.end(), {v00, v10, v11, v00, v11, v01});
        }
        rowIndices = gl::Buffer::create({.bytes = indices.size() * sizeof(std::uint32_t),
                                         .data = indices.data(),
                                         .flags = 0,
                                         .label = "polyvol.grid_row_indices"});
    }
    mVao.elementBuffer(rowIndices);
    mVao.bind();
    const std::int64_t perRow = 2 * std::int64_t(n - 1);
    const std::int64_t fromGrid = std::min(gridTriangles, count);
    const std::int64_t rows = fromGrid / perRow, rest = fromGrid % perRow;
    program.set("uGridRows", 1);
    program.set("uRowOffset", 0);
    if (rows > 0) glDrawElementsInstanced(GL_TRIANGLES, GLsizei(3 * perRow), GL_UNSIGNED_INT, nullptr, GLsizei(rows));
    if (rest > 0) {
        program.set("uRowOffset", int(rows));
        glDrawElementsInstanced(GL_TRIANGLES, GLsizei(3 * rest), GL_UNSIGNED_INT, nullptr, 1);
    }
    const std::int64_t extra = std::min(extraTriangles, count - fromGrid);
    if (extra > 0) {
        keys.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
        program.set("uGridRows", 0);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * extra));
    }
}

void PolyvolTechnique::drawWire(const FrameInput& input, const render::GpuLightCpu& L, const polyvol::VolumeGrid& grid,
                                const gl::Buffer& keys, std::int64_t gridTriangles, std::int64_t extraTriangles,
                                std::int64_t count, const polyvol::AdaptiveTessellation* adaptive) {
    const int wire = mWireMode;
    glm::mat4 viewProj = render::eyeRelativeViewProjection(input.scene->camera, input.width, input.height);
    if (wire == 2) {
        if (grid.mode == polyvol::kModeCube || mWireDrawn) return;
        viewProj = L.shadowMatrix;
    }
    if (wire == 3) viewProj = mMeshView.viewProj();
    mWireDrawn = true;
    mWireProgram.use();
    setGridUniforms(mWireProgram, grid);
    mWireProgram.set("uViewProj", viewProj);
    if (wire == 3) mMeshView.bindTarget();
    else mWireFramebuffer.bind();
    const bool clip = wire == 3 && setOrbitClipBox(*input.scene);
    mWireProgram.set("uClipOn", clip ? 1 : 0);
    for (int k = 0; k < 6 && clip; ++k) glEnable(GLenum(GL_CLIP_DISTANCE0 + k));
    glDisable(GL_BLEND);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    if (adaptive) {
        mWireProgram.set("uGridRows", 0);
        adaptive->keys().bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
        adaptive->counters().bind(GL_DRAW_INDIRECT_BUFFER);
        glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(polyvol::AdaptiveTessellation::drawOffset()));
        keys.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
        glDrawArrays(GL_TRIANGLES, 0, GLsizei(3 * extraTriangles));
    } else {
        drawMesh(mWireProgram, grid, keys, gridTriangles, extraTriangles, count);
    }
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    for (int k = 0; k < 6 && clip; ++k) glDisable(GLenum(GL_CLIP_DISTANCE0 + k));
    glEnable(GL_BLEND);
    mFramebuffer.bind();
    mProgram.use();
}

bool PolyvolTechnique::setOrbitClipBox(const scene::Scene& scene) {
    const render::GpuScene& meshes = mView.gpuScene();  // its bounds are computed once per scene
    if (meshes.triangleCount() == 0) return false;
    scene::Bounds box = meshes.bounds();
    for (const scene::Light& l : scene.lights)
        if (l.type != scene::LightType::Directional) box.lo = glm::min(box.lo, l.position), box.hi = glm::max(box.hi, l.position);
    const glm::dvec3 margin(0.02 * glm::length(box.hi - box.lo));
    const glm::dvec3& eye = scene.camera.position;
    mWireProgram.set("uClipMin", render::toEyeRelative(box.lo - margin, eye));
    mWireProgram.set("uClipMax", render::toEyeRelative(box.hi + margin, eye));
    return true;
}

float PolyvolTechnique::nearRadius(const render::GpuLightCpu& L, const scene::Camera& cam, int height) const {
    const int type = L.info.x;
    if (type == render::hd::kLightDirectional || L.info.z < 0) return 0.0f;
    // A light at the eye: every face of its volume passes through the eye (edge-on: no fragment), and every
    // eye ray is one of its light rays, lit from the eye to the surface. The ball then holds every ray's
    // whole length (past zfar): the resolve pass integrates [0, d] and the crossings add nothing.
    if (render::atEye(L)) return float(2.0 * cam.zfar);
    const float nearest = mView.shadows().nearest(L, L.shadow.y);
    const double footprint = glm::length(glm::dvec3(L.position)) * 2.0 * std::tan(cam.yfov * 0.5) / double(height);
    return float(std::min(0.5 * double(std::max(nearest, 0.0f)), kBallPixels * footprint));
}

void PolyvolTechnique::resolve(const FrameInput& input, int light, float radius) {
    const PolyvolSettings& s = mSettings;
    const scene::Scene& scene = *input.scene;
    const scene::Camera& cam = scene.camera;
    if (!mResolve || mResolveKey != mProgramKey) {
        mResolve = gl::Program::compile(
            {.stages = {"polyvol/resolve.comp"}, .defines = mDefines, .label = "polyvol.resolve"});
        mResolveKey = mProgramKey;
    }
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    mResolve.use();
    render::bindCameraRay(mResolve, cam, input.width, input.height);
    mMedium.bind(scene.medium);
    mResolve.set("uSpotPieces", s.spotPieces);
    mResolve.set("uLightIndex", light);
    mResolve.set("uConstant", s.crackCheck ? 1 : 0);
    mResolve.set("uOriginAtSurface", s.originAtSurface ? 1 : 0);
    mResolve.set("uNearRadius", radius);
    mTotal.bindImage(0, GL_READ_WRITE);
    mPositive.bindImage(1, GL_READ_WRITE);
    mNegative.bindImage(2, GL_READ_WRITE);
    const glm::ivec3 groups = gl::groupCount({input.width, input.height, 1}, mResolve.workGroupSize());
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    glMemoryBarrier(GL_FRAMEBUFFER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    mProgram.use();
}

void PolyvolTechnique::clampAirlight() {
    if (!mClamp) mClamp = gl::Program::compile({.stages = {"polyvol/clamp.comp"}, .label = "polyvol.clamp"});
    mClamp.use();
    mClamp.set("uSize", glm::ivec2(mTotal.size().x, mTotal.size().y));
    mTotal.bindImage(0, GL_READ_ONLY);
    mAirlight.bindImage(1, GL_WRITE_ONLY);
    const glm::ivec3 groups = gl::groupCount({mTotal.size().x, mTotal.size().y, 1}, mClamp.workGroupSize());
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

}  // namespace viz::polyvol_detail
