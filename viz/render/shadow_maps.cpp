#include "render/shadow_maps.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "render/eye_space.h"

namespace viz::render {

namespace {

// Cleared texels are "nothing within the far plane": larger than any distance we compare with.
constexpr float kFarAway = 1.0e30f;

gl::Texture makeArray(int size, int layers, GLenum format, const std::string& label) {
    auto t = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY,
                                  .format = format,
                                  .size = {size, size, std::max(1, layers)},
                                  .label = label});
    t.setFilter(GL_NEAREST, GL_NEAREST);
    t.setWrap(GL_CLAMP_TO_EDGE);
    return t;
}

}  // namespace

void ShadowMaps::cubeFaceBasis(int face, glm::dvec3& forward, glm::dvec3& up) {
    const int axis = face >> 1;
    const double s = (face & 1) == 0 ? 1.0 : -1.0;
    forward = glm::dvec3(0.0);
    forward[axis] = s;
    up = axis == 1 ? glm::dvec3(0.0, 0.0, s) : glm::dvec3(0.0, -1.0, 0.0);
}

ShadowMaps::ShadowMaps()
    : mProgram(gl::Program::compile({.stages = {"render/scene.vert", "render/shadow.frag"},
                                     .label = "render.shadow_program"})),
      mFramebuffer(gl::Framebuffer::create("render.shadow_fbo")) {}

void ShadowMaps::build(const GpuScene& scene, const GpuLights& lights, int size, int vplSize) {
    if (size < 1) throw InputError("shadow_map must be at least 1 texel (got " + std::to_string(size) + ")");
    if (vplSize < 1) throw InputError("VPL shadow map size must be at least 1 (got " + std::to_string(vplSize) + ")");
    const ShadowLayout& layout = lights.shadowLayout();

    // (Re)allocate when sizes or layer counts change; an unused array is 1x1x1.
    auto ensure = [](gl::Texture& t, int texels, int layers, GLenum format, const std::string& label) {
        const int s = layers > 0 ? texels : 1;
        if (!t || t.size() != glm::ivec3(s, s, std::max(1, layers))) t = makeArray(s, layers, format, label);
    };
    ensure(mMaps2D, size, layout.maps2D, GL_R32F, "render.shadow_maps_2d");
    ensure(mCubes, size, 6 * layout.cubes, GL_R32F, "render.shadow_cubes");
    ensure(mVplCubes, vplSize, 6 * layout.vplCubes, GL_R32F, "render.shadow_cubes_vpl");
    const bool needMain = layout.maps2D + layout.cubes > 0;
    if (needMain) ensure(mDepth, size, 1, GL_DEPTH_COMPONENT32F, "render.shadow_depth");
    if (layout.vplCubes > 0) ensure(mDepthVpl, vplSize, 1, GL_DEPTH_COMPONENT32F, "render.shadow_depth_vpl");
    mSize = size;
    mVplSize = vplSize;
    mLayout = layout;
    mLights = lights.lights();
    mReadback.clear();
    mNearest.clear();

    mProgram.use();
    mProgram.set("uModel", eyeRelativeModel(lights.eye()));
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    // Occluders are two-sided: a closed mesh and an open sheet shadow alike.
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);

    auto renderLayer = [&](const gl::Texture& target, const gl::Texture& depth, int layer, int texels,
                           int lightIndex, const glm::mat4& viewProj) {
        mFramebuffer.attachColour(0, target, 0, layer);
        mFramebuffer.attachDepth(depth, 0);
        mFramebuffer.checkComplete();
        mFramebuffer.bind();
        glViewport(0, 0, texels, texels);
        const float clearDistance[4] = {kFarAway, 0.0f, 0.0f, 0.0f};
        glClearNamedFramebufferfv(mFramebuffer.id(), GL_COLOR, 0, clearDistance);
        const float clearDepth = 1.0f;
        glClearNamedFramebufferfv(mFramebuffer.id(), GL_DEPTH, 0, &clearDepth);
        const GpuLightCpu& L = mLights[static_cast<std::size_t>(lightIndex)];
        mProgram.set("uLightPosition", glm::vec3(L.position));
        mProgram.set("uLightDirection", glm::vec3(L.direction));
        mProgram.set("uDirectional", L.info.x == hd::kLightDirectional ? 1 : 0);
        mProgram.set("uViewProj", viewProj);
        scene.draw();
    };

    for (int i = 0; i < lights.count(); ++i) {
        const GpuLightCpu& L = mLights[static_cast<std::size_t>(i)];
        const int index = L.info.z;
        if (index < 0) continue;
        const int type = L.info.x;
        if (type == hd::kLightSpot || type == hd::kLightDirectional) {
            renderLayer(mMaps2D, mDepth, index, size, i, L.shadowMatrix);
            continue;
        }
        // Cube: six faces with 90-degree square frusta, in double then rounded once.
        const bool vpl = type == hd::kLightVpl;
        const glm::dvec3 pos(L.position);
        const glm::dmat4 proj = glm::perspective(std::numbers::pi / 2.0, 1.0, double(L.shadow.x), double(L.shadow.y));
        for (int face = 0; face < 6; ++face) {
            glm::dvec3 forward, up;
            cubeFaceBasis(face, forward, up);
            const glm::mat4 viewProj(proj * glm::lookAt(pos, pos + forward, up));
            renderLayer(vpl ? mVplCubes : mCubes, vpl ? mDepthVpl : mDepth, 6 * index + face,
                        vpl ? vplSize : size, i, viewProj);
        }
    }
    gl::Framebuffer::bindDefault();
    makeViews();
}

void ShadowMaps::makeViews() {
    // Views need a name that was never bound, hence glGenTextures rather than glCreateTextures.
    mViews.clear();
    for (std::size_t i = 0; i < mLights.size(); ++i) {
        const GpuLightCpu& L = mLights[i];
        mViews.emplace_back();
        if (L.info.z < 0) continue;
        GLuint view = 0;
        glGenTextures(1, &view);
        const int type = L.info.x;
        if (type == hd::kLightSpot || type == hd::kLightDirectional) {
            glTextureView(view, GL_TEXTURE_2D, mMaps2D.id(), GL_R32F, 0, 1, GLuint(L.info.z), 1);
        } else {
            const gl::Texture& array = type == hd::kLightVpl ? mVplCubes : mCubes;
            glTextureView(view, GL_TEXTURE_CUBE_MAP, array.id(), GL_R32F, 0, 1, GLuint(6 * L.info.z), 6);
        }
        glTextureParameteri(view, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(view, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        mViews.back() = gl::Handle<gl::TextureTraits>(view);
        gl::setLabel(GL_TEXTURE, view, "render.shadow_map." + std::to_string(i));
    }
}

ShadowMaps::MapLayers ShadowMaps::layersOf(const GpuLightCpu& light) const {
    VIZ_CHECK(light.info.z >= 0, "ShadowMaps: the light has no shadow map");
    const int type = light.info.x;
    const bool flat = type == hd::kLightSpot || type == hd::kLightDirectional;
    const int array = flat ? 0 : (type == hd::kLightVpl ? 2 : 1);
    const MapLayers m{array == 0 ? &mMaps2D : (array == 1 ? &mCubes : &mVplCubes), array,
                      flat ? light.info.z : 6 * light.info.z, flat ? 1 : 6};
    VIZ_CHECK(m.first + m.count <= m.texture->size().z, "ShadowMaps: layer out of range");
    return m;
}

const std::vector<float>& ShadowMaps::texels(const GpuLightCpu& light, int face) const {
    const MapLayers m = layersOf(light);
    VIZ_CHECK(face >= 0 && face < m.count, "ShadowMaps::texels: face out of range");
    const int layer = m.first + face;
    std::vector<float>& values = mReadback[{m.array, layer}];
    if (values.empty()) {
        const gl::Texture& source = *m.texture;
        const int n = source.size().x;
        values.resize(std::size_t(n) * std::size_t(n));
        glPixelStorei(GL_PACK_ALIGNMENT, 4);
        glGetTextureSubImage(source.id(), 0, 0, 0, layer, n, n, 1, GL_RED, GL_FLOAT,
                             GLsizei(values.size() * sizeof(float)), values.data());
    }
    return values;
}

float ShadowMaps::nearest(const GpuLightCpu& light, float upperBound) const {
    const MapLayers m = layersOf(light);
    const auto key = std::make_pair(m.array, m.first);
    if (auto it = mNearest.find(key); it != mNearest.end()) return std::min(it->second, upperBound);
    const gl::Texture& source = *m.texture;
    if (!mNearestProgram)
        mNearestProgram = gl::Program::compile({.stages = {"render/shadow_nearest.comp"}, .label = "render.shadow_nearest"});
    if (!mNearestBuffer) mNearestBuffer = gl::Buffer::create({.bytes = sizeof(std::uint32_t), .label = "render.shadow_nearest"});
    const std::uint32_t start = 0x7f7fffffu;  // FLT_MAX: the shader only lowers it
    mNearestBuffer.upload(0, sizeof start, &start);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
    mNearestProgram.use();
    mNearestProgram.set("uFirstLayer", m.first);
    mNearestProgram.set("uLayers", m.count);
    mNearestProgram.set("uSize", source.size().x);
    source.bindImage(0, GL_READ_ONLY);
    mNearestBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
    const glm::ivec3 groups = gl::groupCount({source.size().x, source.size().y, 1}, mNearestProgram.workGroupSize());
    glDispatchCompute(GLuint(groups.x), GLuint(groups.y), 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::uint32_t bits = 0;
    mNearestBuffer.download(0, sizeof bits, &bits);
    float value = 0.0f;
    std::memcpy(&value, &bits, sizeof value);
    mNearest[key] = value;
    return std::min(value, upperBound);
}

void ShadowMaps::bind() const {
    mMaps2D.bindUnit(hd::kUnitShadow2D);
    mCubes.bindUnit(hd::kUnitShadowCube);
    mVplCubes.bindUnit(hd::kUnitShadowCubeVpl);
}

void ShadowMaps::publish(std::vector<Intermediate>& out, const std::string& prefix) const {
    for (std::size_t i = 0; i < mLights.size(); ++i) {
        const GpuLightCpu& L = mLights[i];
        if (L.info.z < 0) continue;
        const int type = L.info.x;
        Intermediate im;
        im.id = prefix + ".shadow_map" + (i == 0 ? std::string() : "." + std::to_string(i));
        im.kind = ViewKind::Depth;
        im.units = "scene units";
        im.rangeMin = L.shadow.x;
        im.rangeMax = L.shadow.y;
        const std::string source = "scene light " + std::to_string(L.info.w);
        switch (type) {
            case hd::kLightSpot:
            case hd::kLightDirectional:
                im.label = type == hd::kLightSpot ? "Spot shadow map" : "Directional shadow map";
                im.note = (type == hd::kLightSpot ? "distance to the light over the outer cone, "
                                                  : "depth dot(p, direction) over the scene's bounding sphere, ") +
                          source;
                im.glTexture = mViews[i].get();
                im.glTarget = GL_TEXTURE_2D;
                im.extent = glm::ivec3(mSize, mSize, 1);
                break;
            default: {
                const bool vpl = type == hd::kLightVpl;
                im.label = vpl ? "VPL shadow cube" : "Point shadow cube";
                im.note = vpl ? "distance to one sample point of " + source +
                                    "'s area (the shared passes sample an area light at area_samples^2 such "
                                    "points, each with its own cube), cube faces +X -X +Y -Y +Z -Z"
                              : "distance to the light, cube faces +X -X +Y -Y +Z -Z, " + source;
                im.glTexture = mViews[i].get();
                im.glTarget = GL_TEXTURE_CUBE_MAP;
                const int s = vpl ? mVplSize : mSize;
                im.extent = glm::ivec3(s, s, 6);
                break;
            }
        }
        // Texels no occluder covers keep the clear value: hatched and counted, left out of the range.
        im.sentinels = {{kFarAway, "no occluder (cleared far away)"}};
        // One caption per map: the second and later maps carry their index, as their ids do.
        if (i > 0) im.label += " " + std::to_string(i);
        out.push_back(std::move(im));
    }
}

}  // namespace viz::render
