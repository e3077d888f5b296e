// slices' GL passes: shader permutations, targets, the sampling planes drawn back to front and the resolve.
#include "techniques/slices/slices_technique.h"

#include "render/camera_ray.h"

namespace viz::slices_detail {

namespace {

// uDepthFromView (slices/plane_depth.glsl): the surface pass's projection along the view, clip z =
// -P[2][2] z_view + P[3][2] with z_view = -s.
glm::vec2 depthFromView(const scene::Camera& cam, int width, int height) {
    const glm::dmat4 projection = scene::projectionMatrix(cam, width, height);
    return {float(-projection[2][2]), float(projection[3][2])};
}

}  // namespace

gl::ShaderDefines SlicesTechnique::planeDefines(const Terms& t, bool pick) {
    gl::ShaderDefines d;
    if (t.physical) d.push_back({"PHYSICAL", "1"});
    if (t.equiangular) d.push_back({"SLAB_EQUIANGULAR", "1"});
    if (t.spot) d.push_back({"SPOT_FALLOFF", "1"});
    if (t.cookie) d.push_back({"COOKIE", "1"});
    else d.push_back({"LIGHTS_NO_COOKIE", "1"});
    if (t.shadow) d.push_back({"SHADOW", "1"});
    if (t.pcf) d.push_back({"PCF", "1"});
    if (t.noise) d.push_back({"NOISE", "1"});
    if (t.mask) d.push_back({"CHANNEL_MASK", "1"});
    if (t.count && !pick) d.push_back({"COUNT_OUTSIDE", "1"});
    if (t.clip) d.push_back({"CLIP", "1"});
    if (t.userClip) d.push_back({"USER_CLIP", "1"});
    if (pick) d.push_back({"PICK_RAY", "1"});
    // Cube maps serve point lights and area-light VPLs only.
    if (!t.cubes) d.push_back({"SHADOW_NO_CUBE", "1"});
    if (!t.spots) d.push_back({"LIGHTS_NO_SPOT", "1"});
    return d;
}

std::string SlicesTechnique::permutationKey(const Terms& t, bool pick) {
    std::string key;
    for (const auto& [name, value] : planeDefines(t, pick)) key += (key.empty() ? "" : ";") + name;
    return key;
}

void SlicesTechnique::allocateTargets(int width, int height, SlicesAccum accum) {
    const GLenum format = accum == SlicesAccum::Rgba32f ? GL_RGBA32F
                          : accum == SlicesAccum::Rgba16f ? GL_RGBA16F
                                                          : GL_RGBA8;
    if (mAccum && mAccum.size().x == width && mAccum.size().y == height && mAccum.format() == format) return;
    mAccum = gl::Texture::create(
        {.target = GL_TEXTURE_2D, .format = format, .size = {width, height, 1}, .label = kAccum});
    mPlane = gl::Texture::create(
        {.target = GL_TEXTURE_2D, .format = GL_RGBA32F, .size = {width, height, 1}, .label = kPlane});
    mAirlight = gl::Texture::create(
        {.target = GL_TEXTURE_2D, .format = GL_RGBA32F, .size = {width, height, 1}, .label = kAirlight});
    mDepth = gl::Texture::create(
        {.target = GL_TEXTURE_2D, .format = GL_DEPTH_COMPONENT32F, .size = {width, height, 1}, .label = "slices.depth"});
    if (mDepthFramebuffer.id() == 0) mDepthFramebuffer = gl::Framebuffer::create("slices.depth_framebuffer");
    mDepthFramebuffer.attachDepth(mDepth);
}

void SlicesTechnique::setPixelRay(const gl::Program& program, const CameraBasis& basis, const FrameInput& input) {
    const scene::Camera& cam = input.scene->camera;
    program.set("uForward", glm::vec3(basis.forward));
    program.set("uRight", glm::vec3(basis.right));
    program.set("uUp", glm::vec3(basis.up));
    program.set("uSize", glm::vec2(float(input.width), float(input.height)));
    program.set("uTanHalf", float(std::tan(cam.yfov * 0.5)));
    program.set("uAspect", float(scene::aspectOf(cam, input.width, input.height)));
}

void SlicesTechnique::writeSurfaceDepth(const FrameInput& input, const CameraBasis& basis) {
    if (!mDepthProgram)
        mDepthProgram = gl::Program::compile(
            {.stages = {"render/fullscreen.vert", "slices/depth.frag"}, .label = "slices.depth_program"});
    const scene::Camera& cam = input.scene->camera;
    mDepthProgram.use();
    mDepthProgram.set("uDepthFromView", depthFromView(cam, input.width, input.height));
    setPixelRay(mDepthProgram, basis, input);
    mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);  // where the planes read it too
    mDepthFramebuffer.bind();
    glViewport(0, 0, input.width, input.height);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_ALWAYS);
    glDepthMask(GL_TRUE);
    mTriangle->draw();
}

double SlicesTechnique::storeScale(const Terms& t, const SlicesSettings& s) const {
    const SlicesAccum accum = s.accum;
    if (accum == SlicesAccum::Rgba8) return 1.0 / s.accumRange;
    if (accum == SlicesAccum::Rgba8Mask) return 4.0 / s.accumRange;
    (void)t;
    return 1.0;
}

const gl::Program& SlicesTechnique::planeProgram(const Terms& t, bool pick) {
    const std::string key = permutationKey(t, pick);
    auto it = mPlanePrograms.find(key);
    if (it == mPlanePrograms.end()) {
        it = mPlanePrograms
                 .emplace(key, gl::Program::compile({.stages = {"slices/plane.vert", "slices/plane.frag"},
                                                     .defines = planeDefines(t, pick),
                                                     .label = "slices.plane_program"}))
                 .first;
    }
    return it->second;
}

glm::dmat4 SlicesTechnique::cameraVolume(const scene::Camera& cam, int width, int height) {
    const glm::dmat4 view = glm::lookAt(glm::dvec3(0.0), cam.forward, cam.up);
    return glm::perspective(cam.yfov, scene::aspectOf(cam, width, height), cam.znear, cam.zfar) * view;
}

void SlicesTechnique::drawPlanes(const scene::Scene& scene, const FrameInput& input, const Terms& t) {
    const SlicesSettings& s = mSettings;
    const scene::Camera& cam = scene.camera;
    const int n = s.planes;
    const gl::Program& program = planeProgram(t, false);
    // The pick draw's program: the same shader with PICK_RAY; both get every uniform.
    const gl::Program* pick = t.pick ? &planeProgram(t, true) : nullptr;
    auto setBoth = [&](const char* name, auto value) {
        program.set(name, value);
        if (pick) pick->set(name, value);
    };
    mPlanesUsed.clear();
    mPolygons.clear();
    const CameraBasis basis{cam.forward, scene::cameraRight(cam), cam.up};
    const double tanHalf = std::tan(cam.yfov * 0.5);
    const glm::dvec2 viewTan(tanHalf * scene::aspectOf(cam, input.width, input.height), tanHalf);

    program.use();
    setBoth("uViewProj", render::eyeRelativeViewProjection(cam, input.width, input.height));
    setPixelRay(program, basis, input);
    if (pick) setPixelRay(*pick, basis, input);
    mMedium.bind(scene.medium);
    mLastStoreScale = storeScale(t, s);
    setBoth("uStoreScale", float(mLastStoreScale));
    setBoth("uArtisticUnits", float(s.artisticUnits));
    setBoth("uAmbient", float(s.ambient ? kPaperAmbient : 0.0));
    setBoth("uFalloff", s.falloff ? 1 : 0);
    setBoth("uNoiseTiles", float(s.noiseTiles));
    // Two layers scrolling in different directions (slowly: a few hundredths of a tile per second).
    const float time = float(input.controls.time);
    setBoth("uScroll", glm::vec4(0.031f * time, 0.017f * time, -0.023f * time, 0.029f * time));
    setBoth("uPlaneWeight", 1.0f);
    setBoth("uSlabAngle", float(s.slabAngle));
    // User planes: world y >= clip_y_min and y <= clip_y_max, written in eye-relative space.
    const double eyeY = cam.position.y;
    setBoth("uUserPlane0", glm::vec4(0, 1, 0, float(eyeY - s.clipYMin)));
    setBoth("uUserPlane1", glm::vec4(0, -1, 0, float(s.clipYMax - eyeY)));
    setBoth("uDepthFromView", depthFromView(cam, input.width, input.height));

    mView.lights().bind();
    mView.shadows().bind();
    mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
    mNoise.bindUnit(render::hd::kFirstFreeTextureUnit + 1);
    mCounters.bindBase(GL_ATOMIC_COUNTER_BUFFER, 0);
    mVao.bind();

    glViewport(0, 0, input.width, input.height);
    // depth_test=1: a depth buffer made from the first surface's distance (writeSurfaceDepth), tested and
    // never written by the planes (plane.vert places each plane's depth where its part of the ray begins);
    // the count passes and the last plane alone share the test, the pick draw does not (it records the
    // planes beyond the surface too).
    if (t.depthTest) {
        writeSurfaceDepth(input, basis);
        program.use();
        mVao.bind();
        mFramebuffer.attachDepth(mDepth);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDepthMask(GL_FALSE);
    } else {
        mFramebuffer.detachDepth();
        glDisable(GL_DEPTH_TEST);
    }
    glDisable(GL_CULL_FACE);
    // Additive blending: dst = dst + src (the paper's accumulation; saturates in RGBA8).
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    glBlendFunc(GL_ONE, GL_ONE);
    const int clipPlanes = (t.clip ? 6 : 0) + (t.userClip ? 2 : 0);
    for (int i = 0; i < 8; ++i)
        i < clipPlanes ? glEnable(GLenum(GL_CLIP_DISTANCE0 + i)) : glDisable(GLenum(GL_CLIP_DISTANCE0 + i));

    const auto& lights = mView.lights().lights();
    const bool boxedDirectional = s.directionalBox;
    const bool worldGrid = s.worldGrid;
    // Channel mask: one scalar per plane (mean of rgb); the colour ratio of the first light is put back
    // on resolve (exact for one light colour, the paper's monochrome assumption).
    mMaskColour = glm::vec3(1.0f);
    if (!lights.empty()) {
        const glm::dvec3 c = scene.lights[std::size_t(lights.front().info.w)].colour;
        const double mean = (c.r + c.g + c.b) / 3.0;
        if (mean > 0.0) mMaskColour = glm::vec3(c / mean);
    }
    // Draw sets: each spot light (and, with directional_box, each directional light) gets N planes in
    // its own frustum's box, clipped to it. Every other light (point, area-light VPL, directional) lights
    // unbounded space: they share one set of N planes over the camera frustum up to zfar, unclipped
    // (a directional map's box only bounds where shadows are known; outside it V = 1).
    struct DrawSet {
        int light;  // index into lights, or -1: the unbounded lights together
        glm::dmat4 volume;
    };
    std::vector<DrawSet> sets;
    bool unbounded = false;
    for (std::size_t li = 0; li < lights.size(); ++li) {
        const int type = lights[li].info.x;
        if (type == render::hd::kLightSpot || (type == render::hd::kLightDirectional && boxedDirectional))
            sets.push_back({int(li), glm::dmat4(lights[li].shadowMatrix)});
        else
            unbounded = true;
    }
    if (unbounded) sets.push_back({-1, cameraVolume(cam, input.width, input.height)});
    setBoth("uLightCount", mView.lights().count());
    setBoth("uBoxedDirectional", boxedDirectional ? 1 : 0);
    // The picked pixel's records: at most N per draw set (distance scaling only lowers the count).
    mPickSets.clear();
    mPickPixel = pickedPixel(input);
    int pickBase = 0;
    if (t.pick) {
        // plane_grid=world may use up to N + 2 slabs (slice_geometry.h, worldGridRange).
        const std::size_t need = std::max<std::size_t>(1, sets.size() * std::size_t(n + 2)) * sizeof(PickRecord);
        if (!mPickRecords || mPickRecords.bytes() < need)
            mPickRecords = gl::Buffer::create({.bytes = need, .label = "slices.pick_records"});
        mPickRecords.clearZero();
        mPickRecords.bindBase(GL_SHADER_STORAGE_BUFFER, render::hd::kFirstFreeSsboBinding);
        pick->set("uPickPixel", glm::ivec2(mPickPixel.x, input.height - 1 - mPickPixel.y));
    }

    // The planes end at zfar, or with a far camera (zfar 1e6 around a model 10 units across) at the
    // scene's far side: N planes over a million units would all lie beyond every surface.
    const double reach = t.planesEnd;
    for (const DrawSet& set : sets) {
        const bool boxed = set.light >= 0;
        PlaneRange range = planeRange(set.volume, basis, cam.znear, reach, n);
        if (range.empty) continue;
        // Fewer planes far from the light volume (eye at the origin; distance to the view-space box).
        const glm::dvec3 lo(range.minXY, range.near), hi(range.maxXY, range.far);
        const double distance = glm::length(glm::max(glm::max(lo, -hi), glm::dvec3(0.0)));
        range = planeRange(set.volume, basis, cam.znear, reach,
                           scaledPlaneCount(n, distance, s.distanceScale, kMinScaledPlanes));
        if (worldGrid) range = worldGridRange(range, glm::dot(cam.position, basis.forward));
        const int planes = range.planes;
        const int drawnLimit = int(substepLimit(input, kPlanesIndex));
        const int drawn = drawnLimit > 0 ? std::min(planes, drawnLimit) : planes;
        mPlanesUsed.push_back(planes);
        for (auto& poly : planePolygons(range, basis, set.volume, drawn, t.clip && boxed, t.equiangular, viewTan))
            mPolygons.push_back(std::move(poly));
        setBoth("uClipLight", boxed ? 1 : 0);
        setBoth("uFractionOfMaxShells", float(double(planes) / kPaperMaxPlanes));
        setBoth("uLight", set.light);
        setBoth("uLightMatrix", glm::mat4(set.volume));
        setBoth("uBoxMinXY", glm::vec2(range.minXY));
        setBoth("uBoxMaxXY", glm::vec2(range.maxXY));
        setBoth("uDepthFar", float(range.far));
        setBoth("uSpacing", float(range.spacing));
        setBoth("uDrawNear", float(range.drawNear));
        setBoth("uNearestPlane", planes - 1);
        setBoth("uNearestWeight", float(range.nearestWeight));
        if (t.pick) {
            mPickSets.push_back({boxed ? lights[std::size_t(set.light)].info.w : -1, pickBase, drawn,
                                 t.clip && boxed, float(range.far), float(range.spacing), float(range.drawNear),
                                 planes - 1, float(range.nearestWeight), glm::vec2(range.minXY),
                                 glm::vec2(range.maxXY), glm::mat4(set.volume)});
            pick->set("uPickBase", pickBase);
            pickBase += drawn;
        }
        // Back to front: plane 0 is the farthest, so the first k planes are the k farthest.
        mFramebuffer.attachColour(0, mAccum);
        mFramebuffer.checkComplete();
        mFramebuffer.bind();
        glDrawArrays(GL_TRIANGLES, 0, 6 * drawn);
        if (t.lastPlane) {
            // The last plane alone, for stepping and the per-plane readback, its fragments counted; only
            // for a caller that shows slices.plane (its query's result is waited for when the note is
            // written).
            mFramebuffer.attachColour(0, mPlane);
            mFramebuffer.bind();
            if (std::size_t(mPlaneQueriesUsed) == mPlaneQueries.size()) mPlaneQueries.emplace_back();
            gl::SamplesPassedQuery& planeQuery = mPlaneQueries[std::size_t(mPlaneQueriesUsed++)];
            planeQuery.begin();
            glDrawArrays(GL_TRIANGLES, 6 * (drawn - 1), 6);
            planeQuery.end();
        }
        if (pick) {
            // The picked pixel alone with colour writes off: the same planes through the same shader
            // (PICK_RAY), which records what each plane computes there. The frame pays one pixel.
            const glm::ivec2 glPixel(mPickPixel.x, input.height - 1 - mPickPixel.y);
            pick->use();
            glEnable(GL_SCISSOR_TEST);
            glScissor(glPixel.x, glPixel.y, 1, 1);
            glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
            if (t.depthTest) glDisable(GL_DEPTH_TEST);
            glDrawArrays(GL_TRIANGLES, 0, 6 * drawn);
            if (t.depthTest) glEnable(GL_DEPTH_TEST);
            glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
            glDisable(GL_SCISSOR_TEST);
            program.use();
        }
        if (t.count) countFragments(program, drawn);
    }
    for (int i = 0; i < 8; ++i) glDisable(GLenum(GL_CLIP_DISTANCE0 + i));
    glDisable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    mFramebuffer.detachDepth();
    if (t.pick) replayPick(input, basis, t);
    glDisable(GL_BLEND);
    glMemoryBarrier(GL_ATOMIC_COUNTER_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
    gl::Framebuffer::bindDefault();
}

void SlicesTechnique::resolve(const Terms& t, const scene::Scene& scene, const FrameInput& input) {
    gl::ShaderDefines defines;
    if (t.mask) defines.push_back({"CHANNEL_MASK", "1"});
    if (t.blur) defines.push_back({"BLUR", "1"});
    if (t.farTail) {
        // Spots are left out of the tail: their own code is not needed.
        defines.push_back({"FAR_TAIL", "1"});
        defines.push_back({"LIGHTS_NO_SPOT", "1"});
        defines.push_back({"LIGHTS_NO_COOKIE", "1"});
        if (!t.cubes) defines.push_back({"SHADOW_NO_CUBE", "1"});
    }
    std::string key = std::string(t.mask ? "m" : "") + (t.blur ? "b" : "") + (t.farTail ? (t.cubes ? "tc" : "t") : "");
    auto it = mResolvePrograms.find(key);
    if (it == mResolvePrograms.end()) {
        it = mResolvePrograms
                 .emplace(key, gl::Program::compile({.stages = {"render/fullscreen.vert", "slices/resolve.frag"},
                                                     .defines = defines,
                                                     .label = "slices.resolve_program"}))
                 .first;
    }
    const gl::Program& program = it->second;
    program.use();
    program.set("uInvStoreScale", float(1.0 / mLastStoreScale));
    program.set("uMaskColour", mMaskColour);
    if (t.farTail) {
        render::bindCameraRay(program, scene.camera, input.width, input.height);
        program.set("uPlanesEnd", float(t.planesEnd));
        program.set("uLightCount", mView.lights().count());
        program.set("uBoxedDirectional", mSettings.directionalBox ? 1 : 0);
        mMedium.bind(scene.medium);
        mView.lights().bind();
        mView.shadows().bind();
        mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
    }
    mFramebuffer.attachColour(0, mAirlight);
    mFramebuffer.checkComplete();
    mFramebuffer.bind();
    glViewport(0, 0, mAirlight.size().x, mAirlight.size().y);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    mAccum.bindUnit(0);
    mTriangle->draw();
    gl::Framebuffer::bindDefault();
}

}  // namespace viz::slices_detail
