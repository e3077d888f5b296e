// What polyvol shows: its intermediates, the lookup table's error against the analytic integral and the
// markers of a picked pixel.
#include "techniques/polyvol/polyvol_technique.h"

namespace viz::polyvol_detail {

std::vector<ViewMarker> PolyvolTechnique::markersFor(glm::ivec2 pixel, const std::string& id) const {
    int index = render::shadowMapIndexOf(id, "polyvol");
    // The edge and level maps are the last adaptive light's.
    if (index < 0 && (id == kEdgeMap || id == kTessLevels) && !mAdaptiveLights.empty()) index = mAdaptiveLights.back();
    if (index < 0 || index >= mView.lights().count()) return {};
    const render::GpuLightCpu& L = mView.lights().lights()[std::size_t(index)];
    const bool flat = L.info.x == render::hd::kLightSpot || L.info.x == render::hd::kLightDirectional;
    if (L.info.z < 0 || (!flat && (id == kEdgeMap || id == kTessLevels))) return {};
    glm::dvec3 w;
    double d = 0.0;
    if (!mView.pixelRay(pixel, w, d)) return {};
    const int n = mView.shadows().size();
    polyvol::VolumeGrid grid = describe(L, index, n, mMarkZfar, mMarkCookieMask);
    // An adaptive volume: its triangles as emitted, read back. The last adaptive 2D light's and the last
    // adaptive cube's are still in their buffers; the others are built again, as the run built them.
    const bool adaptive = std::find(mAdaptiveLights.begin(), mAdaptiveLights.end(), index) != mAdaptiveLights.end();
    const std::vector<std::uint32_t>* keys = nullptr;
    if (adaptive) {
        grid.keyStride = grid.mapSize + 1;
        keys = index == (flat ? mFlatAdaptiveLight : mCubeAdaptiveLight) ? &adaptiveKeys(!flat) : &rebuiltKeys(index, grid);
    }
    std::vector<polyvol::VolumeCrossing> crossings;
    if (flat) {
        crossings = polyvol::volumeCrossings(grid, L, mView.shadows().texels(L, 0), w, keys);
    } else {
        std::array<const std::vector<float>*, 6> faces{};
        for (int f = 0; f < 6; ++f) faces[std::size_t(f)] = &mView.shadows().texels(L, f);
        crossings = polyvol::cubeVolumeCrossings(grid, L, faces, w, keys);
    }
    int sum = 0;
    for (const polyvol::VolumeCrossing& c : crossings) sum += c.sign;
    std::vector<ViewMarker> marks;
    char text[160];
    // Cube maps: marks on the face (layer) the point's direction from the light selects.
    const auto faceOf = [&](const glm::dvec3& p) {
        if (flat) return 0;
        const glm::dvec3 v = p - glm::dvec3(L.position), a = glm::abs(v);
        const int axis = (a.x >= a.y && a.x >= a.z) ? 0 : (a.y >= a.z ? 1 : 2);
        return 2 * axis + (v[axis] < 0.0 ? 1 : 0);
    };
    for (const render::MapStretch& s : render::walkShadowMap(mView.shadows(), L, w, d).stretches) {
        std::snprintf(text, sizeof text, "eye ray t=%.2f..%.2f: %d crossings, signed %+d", s.t0, s.t1,
                      int(crossings.size()), sum);
        marks.push_back({render::shadowMapUv(L, s.face, s.t0 * w), render::shadowMapUv(L, s.face, s.t1 * w), text,
                         flat ? -1 : s.face});
    }
    for (const polyvol::VolumeCrossing& c : crossings) {
        const int face = faceOf(c.t * w);
        const glm::vec2 uv = render::shadowMapUv(L, face, c.t * w);
        // Crossings on a directional volume's skirt lie outside the map: not drawable there.
        if (!(uv.x >= -1e-3f && uv.y >= -1e-3f && uv.x <= 1.001f && uv.y <= 1.001f)) continue;
        std::snprintf(text, sizeof text, c.sign > 0 ? "+1 leaves lit t=%.2f%s" : "-1 enters lit t=%.2f%s", c.t,
                      c.t > d ? " (beyond d)" : "");
        marks.push_back({uv, uv, text, flat ? -1 : face});
    }
    return marks;
}

std::vector<std::uint32_t> PolyvolTechnique::downloadKeys(const polyvol::AdaptiveTessellation& tess) {
    const std::size_t count = std::size_t(std::max<std::int64_t>(0, tess.triangles())) * 3;
    std::vector<std::uint32_t> keys(std::min(count, tess.keys().bytes() / sizeof(std::uint32_t)), 0u);
    if (!keys.empty()) tess.keys().download(0, keys.size() * sizeof(std::uint32_t), keys.data());
    return keys;
}

const std::vector<std::uint32_t>& PolyvolTechnique::adaptiveKeys(bool cube) const {
    std::vector<std::uint32_t>& keys = mMarkKeys[cube ? 1 : 0];
    if (!mMarkKeysRead[cube ? 1 : 0]) {
        keys = downloadKeys(cube ? mTessCube : mTess);
        mMarkKeysRead[cube ? 1 : 0] = true;
    }
    return keys;
}

const std::vector<std::uint32_t>& PolyvolTechnique::rebuiltKeys(int index, const polyvol::VolumeGrid& grid) const {
    const auto found = mRebuiltKeys.find(index);
    if (found != mRebuiltKeys.end()) return found->second;
    // The same build as the run's (its grid, settings, shadow maps and light buffer): the same triangles,
    // whatever order the atomics appended them in.
    mView.lights().bind();
    mView.shadows().bind();
    mMarkTess.build(grid, mMarkMeasure, mMarkThreshold, mMarkStopLevel, mDefines, mProgramKey);
    return mRebuiltKeys[index] = downloadKeys(mMarkTess);
}

float PolyvolTechnique::lutError(const FrameInput& input) {
    const scene::Scene& scene = *input.scene;
    const scene::Camera& cam = scene.camera;
    if (!mLutErrorProgram) {
        mLutErrorProgram = gl::Program::compile({.stages = {"polyvol/lut_error.comp"},
                                                 .defines = {{"AIRLIGHT_LUT", "1"}},
                                                 .label = "polyvol.lut_error"});
    }
    if (!mLutError || mLutError.size().x != input.width || mLutError.size().y != input.height) {
        mLutError = gl::Texture::create({.target = GL_TEXTURE_2D, .format = GL_R32F,
                                         .size = {input.width, input.height, 1}, .levels = 1, .label = kLutError});
    }
    const gl::Program& p = mLutErrorProgram;
    p.use();
    render::bindCameraRay(p, cam, input.width, input.height);
    mMedium.bind(scene.medium);
    p.set("uLightCount", mView.lights().count());
    mView.lights().bind();
    mView.surface().distance().bindUnit(render::hd::kFirstFreeTextureUnit);
    mLut.bindUnit(render::hd::kFirstFreeTextureUnit + 1);
    mLutError.bindImage(0, GL_WRITE_ONLY);
    const glm::ivec3 groups = gl::groupCount({input.width, input.height, 1}, p.workGroupSize());
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    const Image e = gl::readTexture(mLutError);
    float worst = 0.0f;
    for (float v : e.pixels) worst = std::max(worst, v);
    return worst;
}

void PolyvolTechnique::publishVolume(FrameOutput& out, const FrameInput& input, std::int64_t triangles) {
    const PolyvolSettings& s = mSettings;
    const bool constant = s.crackCheck;
    const std::string count = std::to_string(triangles) + " triangles drawn" +
                              (mAdaptiveOverflow ? " (adaptive buffers overflowed: mesh cut short)" : "");
    mTriangles = triangles;
    if (mShownTess) {
        out.intermediates.push_back(render::textureIntermediate(
            kEdgeMap, "Edge map",
            std::string(s.edgeMeasure == polyvol::EdgeMeasure::Laplacian ? "|Laplacian|" : "sum of |second differences| (x, y, diagonals)") +
                " of the vertex depths (spot, cube faces: of their reciprocals, scaled to a depth) / the map's depth "
                "range (the last adaptive light; a cube's six faces are its layers)",
            "", ViewKind::Scalar, 0.0f, float(std::max(1e-6, 10.0 * s.threshold)), mShownTess->edgeMap()));
        out.intermediates.push_back(render::textureIntermediate(
            kTessLevels, "Tessellation level", "leaf level k of each texel's quad (2^k texels wide), stored k/16; " +
            count, "", ViewKind::Scalar, 0.0f, float(mShownTess->levels()) / 16.0f, mShownTess->levelMap()));
    }
    Intermediate mesh;
    if (mWireMode == 3) {
        mesh = render::textureIntermediate(kMesh, "Light volume mesh", "", "", ViewKind::Colour, 0.0f, 1.0f,
                                           mMeshView.texture());
    } else if (mWireMode != 0 && mWire) {
        mesh = render::textureIntermediate(kMesh, "Light volume mesh", "", "", ViewKind::Colour, 0.0f, 1.0f, mWire);
    }
    mesh.id = kMesh;
    mesh.label = "Light volume mesh";
    mesh.note = count + " (grid: one vertex per shadow-map texel; closure to the light / cap; cube seams)" +
                (mWireMode != 0 ? "; wireframe: green = rays leave (+L), red = rays enter (-L)" +
                                                std::string(mWireMode == 3
                                                                ? "; blue: camera frustum, yellow: lights; clipped to the "
                                                                  "box around the scene and its lights (a sun's volume "
                                                                  "reaches the far plane)"
                                                                : "")
                                          : "; wireframe=camera|light|orbit draws it (orbit: a view of its own)") +
                (mWireMode == 3 && s.wireframe == 0 ? "; drawn because this view is shown (its time counts in the volume stage)" : "");
    mesh.kind = mWireMode != 0 ? ViewKind::Colour : ViewKind::Mesh;
    mesh.orbit = mWireMode == 3;
    mesh.picture = mWireMode != 0;
    out.intermediates.push_back(mesh);
    out.intermediates.push_back(render::textureIntermediate(
        kCrossings, "Crossings",
        "r: volume faces crossed by each pixel's ray (overdraw), g: signed count, b: crossings in front of the "
        "near plane (kept by the depth clamp), a: crossings beyond the surface (clamped to d); " + count, "",
        ViewKind::Scalar, 0.0f, 16.0f, mCrossings));
    out.intermediates.back().channels = {{"faces crossed (overdraw)", "faces", ViewKind::Scalar, 0.0f, 16.0f},
                                         {"signed count", "faces", ViewKind::Signed, -4.0f, 4.0f},
                                         {"crossings before the near plane", "faces", ViewKind::Scalar, 0.0f, 4.0f},
                                         {"crossings beyond the surface", "faces", ViewKind::Scalar, 0.0f, 4.0f}};
    out.intermediates.back().rangeGrowsToData = true;  // tv-room's 17 overlapping volumes exceed 16 everywhere
    const std::string units = constant ? "scene units (lit length)" : "radiance";
    out.intermediates.push_back(render::textureIntermediate(
        kPositive, "Positive terms", "sum of +L(0, x) where rays leave the lit volume, plus the chord through the ball around the light", units, ViewKind::Colour,
        0.0f, 1.0f, mPositive));
    out.intermediates.push_back(render::textureIntermediate(
        kNegative, "Negative terms", "sum of L(0, x) where rays enter the lit volume (subtracted)", units,
        ViewKind::Colour, 0.0f, 1.0f, mNegative));
    std::string balls;
    for (float r : mNearRadii) {
        char text[32];
        std::snprintf(text, sizeof text, "%s%.3g", balls.empty() ? "" : ", ", double(r));
        balls += text;
    }
    out.intermediates.push_back(render::textureIntermediate(
        kTotal, "Signed total",
        "positive - negative (unclamped; L_air = max(0, total)); each ray's chord through a ball around each "
        "light, radius half its map's nearest distance (" + (balls.empty() ? std::string("none") : balls) +
            "; 0: none), is added once per pixel, not by crossings",
        units, ViewKind::Signed, -1.0f, 1.0f, mTotal));
    out.intermediates.back().rangeFromData = true;  // the light's peak would wash out the rest at a fixed range
    const Image total = gl::readTexture(mCrossings);
    const polyvol::CrackReport report = polyvol::countCrackPixels(total, 1);
    auto mask = std::make_shared<Image>(total.width, total.height, 1);
    for (int y = 0; y < total.height; ++y)
        for (int x = 0; x < total.width; ++x)
            mask->at(x, y) = std::fabs(total.at(x, y, 1) - float(report.expected)) < 1e-3f ? 0.0f : 1.0f;
    Intermediate cracks;
    cracks.id = kCracks;
    cracks.label = "Crack pixels";
    cracks.note = std::to_string(report.badPixels) + " bad pixels (signed crossing count != " +
                  std::to_string(report.expected) + ", the volumes containing the eye)";
    cracks.kind = ViewKind::Mask;
    cracks.image = mask;
    cracks.extent = {total.width, total.height, 1};
    out.intermediates.push_back(cracks);
    render::readBackAirlight(input, mAirlight, out);
}

}  // namespace viz::polyvol_detail
