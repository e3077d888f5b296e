#include "render/gpu_lights.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "render/gpu_scene.h"
#include "render/light_culling.h"
#include "scene/texture_sampling.h"

namespace viz::render {

namespace {

// Shadow bias: the stored distance is compared with the query plus
//   shadow.w (a constant, 1e-4 of the scene radius) + shadow.z * (distance or 1) / mapSize,
// i.e. kBiasTexels texel footprints; two footprints cover receivers tilted up to ~63 degrees from the map's
// view direction without acne. Larger tilts are grazing, where Lambert's cosine is small anyway.
constexpr double kBiasTexels = 2.0;
constexpr double kBiasRelative = 1e-4;
// Spot maps are perspective frusta over the outer cone; wider cones are clipped to this half-angle
// (points outside the frustum count as lit; A_spot is tiny there).
constexpr double kMaxSpotHalfAngle = 85.0 * std::numbers::pi / 180.0;

// Frame of a spot (cookie and shadow map): z = axis, x = right, y = up, from world up (0,1,0), or
// (1,0,0) when the axis is nearly vertical. Same rule as the definition (and the reference).
void spotFrame(const glm::dvec3& z, glm::dvec3& x, glm::dvec3& y) {
    const glm::dvec3 worldUp = std::abs(z.y) > 0.999 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    x = glm::normalize(glm::cross(z, worldUp));
    y = glm::cross(x, z);
}

struct ShadowRange {
    double near = 1e-3, far = 1.0;
};

// Near/far planes for a map centred at `origin` (eye-relative) that must see the whole scene.
ShadowRange rangeFrom(const glm::dvec3& origin, const glm::dvec3& center, double radius) {
    const double far = (glm::length(center - origin) + radius) * 1.01 + 1e-6;
    return ShadowRange{far * 1e-4, far};
}

// Each spot cookie's layer of the cookie array, in the order the lights first use them.
std::map<int, int> cookieLayers(const scene::Scene& scene) {
    std::map<int, int> layerOf;
    for (const auto& light : scene.lights) {
        if (light.type != scene::LightType::Spot || light.cookie < 0) continue;
        if (light.cookie >= static_cast<int>(scene.textures.size())) {
            throw InputError("light '" + light.name + "': cookie texture " + std::to_string(light.cookie) +
                             " does not exist");
        }
        if (!layerOf.count(light.cookie)) layerOf.emplace(light.cookie, static_cast<int>(layerOf.size()));
    }
    return layerOf;
}

gl::Texture uploadCookies(const scene::Scene& scene, const std::map<int, int>& layerOf) {
    int width = 1, height = 1;
    for (const auto& [texture, layer] : layerOf) {
        const auto& t = scene.textures[static_cast<std::size_t>(texture)];
        width = std::max(width, t.width);
        height = std::max(height, t.height);
    }
    const int layers = std::max(1, static_cast<int>(layerOf.size()));
    auto array = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY,
                                      .format = GL_RGBA8,  // sRGB bytes, decoded in the shader
                                      .size = {width, height, layers},
                                      .label = "render.cookies"});
    array.setFilter(GL_NEAREST, GL_NEAREST);
    array.setWrap(GL_CLAMP_TO_EDGE);
    if (layerOf.empty()) {
        const std::uint8_t white[4] = {255, 255, 255, 255};
        array.uploadRegion({0, 0, 0}, {1, 1, 1}, GL_RGBA, GL_UNSIGNED_BYTE, white);
    }
    for (const auto& [texture, layer] : layerOf) {
        const auto& t = scene.textures[static_cast<std::size_t>(texture)];
        // Row 0 (top, v = 0) to texel row 0: texel y = v * height, as in scene::sampleLinearRgb.
        array.uploadRegion({0, 0, layer}, {t.width, t.height, 1}, GL_RGBA, GL_UNSIGNED_BYTE, t.rgba8.data());
    }
    return array;
}

}  // namespace


LightDescription describeLights(const scene::Scene& scene, glm::dvec3 eye, int areaSamples, VplKernel kernel) {
    if (areaSamples < 1) {
        throw InputError("area_samples must be at least 1 (got " + std::to_string(areaSamples) + ")");
    }
    // Scene bounds, eye-relative: they size every shadow map.
    const scene::Bounds world = scene::sceneBounds(scene);
    const glm::dvec3 center = world.centre() - eye;
    const double radius = std::max(world.radius(), 1e-6);
    const double biasConstant = kBiasRelative * radius;

    LightDescription out;
    out.cookieLayers = cookieLayers(scene);
    const std::map<int, int>& cookieLayer = out.cookieLayers;
    std::vector<GpuLightCpu>& lights = out.lights;
    ShadowLayout& layout = out.layout;

    for (std::size_t li = 0; li < scene.lights.size(); ++li) {
        const scene::Light& light = scene.lights[li];
        // A light whose lit volume misses the view volume lights nothing visible: no entry, no shadow map.
        if (!lightReachesView(light, scene.camera)) continue;
        GpuLightCpu g{};
        g.position = glm::vec4(glm::vec3(light.position - eye), 1.0f);
        g.direction = glm::vec4(glm::vec3(glm::normalize(light.direction)), 0.0f);
        g.radiant = glm::vec4(glm::vec3(light.colour * light.intensity), 0.0f);
        g.spot = glm::vec4(0.0f);
        g.frameX = glm::vec4(1, 0, 0, 1);
        g.frameY = glm::vec4(0, 1, 0, 1);
        g.info = glm::ivec4(0, -1, -1, static_cast<int>(li));
        g.shadowMatrix = glm::mat4(1.0f);
        const glm::dvec3 pos = light.position - eye;

        switch (light.type) {
            case scene::LightType::Point: {
                g.info.x = hd::kLightPoint;
                g.info.z = layout.cubes++;
                const ShadowRange r = rangeFrom(pos, center, radius);
                // A cube face spans 90 degrees: a texel at distance d covers ~2 d / size.
                g.shadow = glm::vec4(float(r.near), float(r.far), float(kBiasTexels * 2.0), float(biasConstant));
                lights.push_back(g);
                break;
            }
            case scene::LightType::Spot: {
                g.info.x = hd::kLightSpot;
                const glm::dvec3 axis = glm::normalize(light.direction);
                glm::dvec3 fx, fy;
                spotFrame(axis, fx, fy);
                const double cosInner = std::cos(light.innerConeAngle);
                const double cosOuter = std::cos(light.outerConeAngle);
                // KHR_lights_punctual angular attenuation: A = clamp(cd * scale + offset, 0, 1)^2.
                const double scale = 1.0 / std::max(0.001, cosInner - cosOuter);
                const double offset = -cosOuter * scale;
                g.spot = glm::vec4(float(scale), float(offset), float(std::tan(light.outerConeAngle)),
                                   float(cosOuter));
                g.frameX = glm::vec4(glm::vec3(fx), 1.0f);
                g.frameY = glm::vec4(glm::vec3(fy), 1.0f);
                if (light.cookie >= 0) {
                    const auto& t = scene.textures[static_cast<std::size_t>(light.cookie)];
                    g.info.y = cookieLayer.at(light.cookie);
                    g.frameX.w = float(t.width);
                    g.frameY.w = float(t.height);
                }
                g.info.z = layout.maps2D++;
                const ShadowRange r = rangeFrom(pos, center, radius);
                const double half = std::min(light.outerConeAngle, kMaxSpotHalfAngle);
                const glm::dmat4 proj = glm::perspective(2.0 * half, 1.0, r.near, r.far);
                const glm::dmat4 view = glm::lookAt(pos, pos + axis, fy);
                g.shadowMatrix = glm::mat4(proj * view);
                // Texel footprint at distance d along the axis: 2 d tan(half) / size.
                g.shadow = glm::vec4(float(r.near), float(r.far), float(kBiasTexels * 2.0 * std::tan(half)),
                                     float(biasConstant));
                lights.push_back(g);
                break;
            }
            case scene::LightType::Directional: {
                g.info.x = hd::kLightDirectional;
                const glm::dvec3 dir = glm::normalize(light.direction);
                glm::dvec3 fx, fy;
                spotFrame(dir, fx, fy);
                g.frameX = glm::vec4(glm::vec3(fx), 1.0f);
                g.frameY = glm::vec4(glm::vec3(fy), 1.0f);
                g.info.z = layout.maps2D++;
                // Orthographic map over the scene's bounding sphere, looking along the travel direction.
                const double r = radius * 1.01;
                const glm::dvec3 from = center - dir * r;
                const glm::dmat4 proj = glm::ortho(-r, r, -r, r, 0.0, 2.0 * r);
                const glm::dmat4 view = glm::lookAt(from, center, fy);
                g.shadowMatrix = glm::mat4(proj * view);
                // The map stores dot(p, direction), within dot(center, direction) +- r (shadow.xy, for
                // display); the texel footprint is the constant 2 r / size.
                const double mid = glm::dot(center, dir);
                g.shadow = glm::vec4(float(mid - r), float(mid + r), float(kBiasTexels * 2.0 * r), float(biasConstant));
                lights.push_back(g);
                break;
            }
            case scene::LightType::Area: {
                // areaSamples^2 VPLs at the centres of areaSamples x areaSamples equal cells of the
                // emitter, p = centre + s halfU + t halfV with s, t = (2i + 1) / n - 1, dA = 4 |halfU x halfV|
                // / n^2. A VPL's colour is the texture's mean over its cell, so the VPLs carry the emitter's
                // whole power and colour, not the texture at areaSamples^2 points; near the emitter the air
                // and the surfaces see the cell's solid angle (lights.glsl). Equal cells, not the
                // Gauss-Legendre nodes and the cells their weights give (wider at the middle, where most
                // of the light is): tv-room at 160x120, raymarch against the reference, 8^2 VPLs 0.059 ->
                // 0.039 (final image 0.0079 -> 0.0053), 16^2 0.021 -> 0.015, 4^2 0.085 -> 0.084; points
                // (vpl_kernel=point) too, 8^2 0.124 -> 0.097 (docs/numerics.md, "A VPL's cell").
                const double jacobian = glm::length(glm::cross(light.halfU, light.halfV));
                const scene::Texture* tex = nullptr;
                if (light.emissionTexture >= 0) {
                    if (light.emissionTexture >= static_cast<int>(scene.textures.size())) {
                        throw InputError("light '" + light.name + "': emission texture does not exist");
                    }
                    tex = &scene.textures[static_cast<std::size_t>(light.emissionTexture)];
                }
                const auto edge = [&](int k) { return double(k) / areaSamples; };  // the k-th cell edge in uv
                const double width = 2.0 / areaSamples;  // a cell's side in s and t
                for (int j = 0; j < areaSamples; ++j) {
                    for (int i = 0; i < areaSamples; ++i) {
                        const double s = (i + 0.5) * width - 1.0;
                        const double t = (j + 0.5) * width - 1.0;
                        const double dA = jacobian * width * width;
                        glm::dvec3 le = light.radiance;
                        if (tex)
                            le *= scene::averageLinearRgb(*tex, {edge(i), edge(j)}, {edge(i + 1), edge(j + 1)});
                        GpuLightCpu v = g;
                        const glm::dvec3 p = pos + s * light.halfU + t * light.halfV;
                        // w: the kernel (shaders/common/lights.glsl, vplHasCell): 1, the node's cell, whose
                        // corner, edges and area ride in spot, frameX and frameY; 0, a point.
                        v.position = glm::vec4(glm::vec3(p), kernel == VplKernel::Cell ? 1.0f : 0.0f);
                        v.radiant = glm::vec4(glm::vec3(le * dA), 0.0f);
                        v.info = glm::ivec4(hd::kLightVpl, -1, layout.vplCubes++, static_cast<int>(li));
                        const double s0 = 2.0 * edge(i) - 1.0, s1 = 2.0 * edge(i + 1) - 1.0;
                        const double t0 = 2.0 * edge(j) - 1.0, t1 = 2.0 * edge(j + 1) - 1.0;
                        v.spot = glm::vec4(glm::vec3(pos + s0 * light.halfU + t0 * light.halfV), float(dA));
                        v.frameX = glm::vec4(glm::vec3((s1 - s0) * light.halfU), 0.0f);
                        v.frameY = glm::vec4(glm::vec3((t1 - t0) * light.halfV), 0.0f);
                        const ShadowRange r = rangeFrom(p, center, radius);
                        v.shadow = glm::vec4(float(r.near), float(r.far), float(kBiasTexels * 2.0),
                                             float(biasConstant));
                        lights.push_back(v);
                    }
                }
                break;
            }
        }
    }

    return out;
}

GpuLights::GpuLights(const scene::Scene& scene, glm::dvec3 eye, int areaSamples, VplKernel kernel) : mEye(eye) {
    LightDescription described = describeLights(scene, eye, areaSamples, kernel);
    mLights = std::move(described.lights);
    mLayout = described.layout;
    mCookies = uploadCookies(scene, described.cookieLayers);
    mCookieCount = int(described.cookieLayers.size());
    if (mLights.size() > static_cast<std::size_t>(hd::kMaxGpuLights)) {
        throw InputError("the scene needs " + std::to_string(mLights.size()) + " GPU lights (area lights count " +
                         std::to_string(areaSamples) + "^2 each) but at most " + std::to_string(hd::kMaxGpuLights) +
                         " are supported: lower area_samples");
    }
    GLint maxBlock = 0;
    glGetIntegerv(GL_MAX_UNIFORM_BLOCK_SIZE, &maxBlock);
    VIZ_CHECK(static_cast<std::size_t>(maxBlock) >= hd::kMaxGpuLights * sizeof(GpuLightCpu),
              "GL_MAX_UNIFORM_BLOCK_SIZE is too small for kMaxGpuLights lights");
    // Full capacity (48 KB): a uniform block must be backed by as many bytes as it declares.
    std::vector<GpuLightCpu> upload = mLights;
    upload.resize(static_cast<std::size_t>(hd::kMaxGpuLights), GpuLightCpu{});
    mBuffer = gl::Buffer::create({.bytes = upload.size() * sizeof(GpuLightCpu),
                                  .data = upload.data(),
                                  .label = "render.lights"});
}

void GpuLights::bind() const {
    mBuffer.bindBase(GL_SHADER_STORAGE_BUFFER, hd::kBindingLights);
    mBuffer.bindBase(GL_UNIFORM_BUFFER, hd::kBindingLightsUniform);
    mCookies.bindUnit(hd::kUnitCookies);
}

}  // namespace viz::render
