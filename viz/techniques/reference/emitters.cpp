#include "techniques/reference/emitters.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "scene/texture_sampling.h"
#include "shared/gauss_legendre.h"
#include "techniques/reference/quadrature.h"

namespace viz::reference {

// ---- textures ----

LinearTexture::LinearTexture(const scene::Texture& texture) : mWidth(texture.width), mHeight(texture.height) {
    VIZ_CHECK(texture.rgba8.size() == std::size_t(mWidth) * std::size_t(mHeight) * 4u,
              "texture '" + texture.name + "' has the wrong byte count");
    // Decode once: 256-entry table.
    double table[256];
    for (int i = 0; i < 256; ++i) table[i] = scene::srgbToLinearExact(i / 255.0);
    mTexels.resize(std::size_t(mWidth) * std::size_t(mHeight));
    for (std::size_t i = 0; i < mTexels.size(); ++i) {
        mTexels[i] = glm::dvec3(table[texture.rgba8[4 * i + 0]], table[texture.rgba8[4 * i + 1]],
                                table[texture.rgba8[4 * i + 2]]);
    }
}

glm::dvec3 LinearTexture::sample(glm::dvec2 uv) const {
    if (mWidth == 0) return glm::dvec3(1.0);
    // Texel space: texel (i, j) has its centre at (i + 0.5, j + 0.5); uv outside [0,1] clamps.
    const double fx = std::clamp(uv.x, 0.0, 1.0) * mWidth - 0.5;
    const double fy = std::clamp(uv.y, 0.0, 1.0) * mHeight - 0.5;
    const double x0f = std::floor(fx), y0f = std::floor(fy);
    const double ax = fx - x0f, ay = fy - y0f;
    const int x0 = std::clamp(int(x0f), 0, mWidth - 1), x1 = std::clamp(int(x0f) + 1, 0, mWidth - 1);
    const int y0 = std::clamp(int(y0f), 0, mHeight - 1), y1 = std::clamp(int(y0f) + 1, 0, mHeight - 1);
    const glm::dvec3 top = (1.0 - ax) * texel(x0, y0) + ax * texel(x1, y0);
    const glm::dvec3 bottom = (1.0 - ax) * texel(x0, y1) + ax * texel(x1, y1);
    return (1.0 - ay) * top + ay * bottom;
}

// ---- spot lights ----

void spotFrame(const glm::dvec3& s, glm::dvec3& right, glm::dvec3& up) {
    const glm::dvec3 worldUp = std::abs(s.y) > 0.999 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    right = glm::normalize(glm::cross(s, worldUp));
    up = glm::cross(right, s);
}

SpotProfile SpotProfile::fromLight(const scene::Light& light, const LinearTexture* cookie) {
    SpotProfile p;
    p.axis = glm::normalize(light.direction);
    spotFrame(p.axis, p.right, p.up);
    p.cosInner = std::cos(light.innerConeAngle);
    p.cosOuter = std::cos(light.outerConeAngle);
    // KHR_lights_punctual: scale = 1 / max(0.001, cos(inner) - cos(outer)), offset = -cos(outer) scale.
    p.scale = 1.0 / std::max(0.001, p.cosInner - p.cosOuter);
    p.offset = -p.cosOuter * p.scale;
    p.tanOuter = std::tan(light.outerConeAngle);
    p.cookie = (cookie && !cookie->empty()) ? cookie : nullptr;
    return p;
}

double SpotProfile::attenuation(const glm::dvec3& dirFromLight) const {
    const double cd = glm::dot(axis, dirFromLight);
    const double a = std::clamp(cd * scale + offset, 0.0, 1.0);
    return a * a;
}

glm::dvec2 SpotProfile::cookieUv(const glm::dvec3& dirFromLight) const {
    const double z = glm::dot(axis, dirFromLight);
    const double x = glm::dot(right, dirFromLight), y = glm::dot(up, dirFromLight);
    return glm::dvec2(0.5 + 0.5 * x / (z * tanOuter), 0.5 + 0.5 * y / (z * tanOuter));
}

glm::dvec3 SpotProfile::evaluate(const glm::dvec3& dirFromLight) const {
    const double a = attenuation(dirFromLight);
    if (a == 0.0) return glm::dvec3(0.0);
    if (!cookie) return glm::dvec3(a);
    return a * cookie->sample(cookieUv(dirFromLight));
}

// ---- emitters ----

glm::dvec3 PointEmitter::profile(const glm::dvec3& dirFromLight) const {
    switch (kind) {
        case ProfileKind::Isotropic: return glm::dvec3(1.0);
        case ProfileKind::Spot: return spot->evaluate(dirFromLight);
        case ProfileKind::Lambertian: return glm::dvec3(std::max(0.0, glm::dot(normal, dirFromLight)));
    }
    return glm::dvec3(0.0);
}

glm::dvec3 areaRadiance(const scene::Light& light, const std::vector<LinearTexture>& textures, glm::dvec2 uv) {
    glm::dvec3 le = light.radiance;
    if (light.emissionTexture >= 0 && std::size_t(light.emissionTexture) < textures.size()) {
        le *= textures[std::size_t(light.emissionTexture)].sample(uv);
    }
    return le;
}

PreparedLights PreparedLights::build(const scene::Scene& scene, int areaSamples) {
    PreparedLights out;
    out.lightCount = int(scene.lights.size());
    out.textures.reserve(scene.textures.size());
    for (const auto& t : scene.textures) out.textures.emplace_back(t);
    // Reserve so that the pointers PointEmitter::spot keeps stay valid.
    out.spots.reserve(scene.lights.size());
    const QuadratureRule rule = gaussLegendreRuleUnit(std::max(1, areaSamples));
    for (std::size_t li = 0; li < scene.lights.size(); ++li) {
        const scene::Light& light = scene.lights[li];
        switch (light.type) {
            case scene::LightType::Point:
            case scene::LightType::Spot: {
                PointEmitter e;
                e.position = light.position;
                e.intensity = light.intensity * light.color;
                e.light = int(li);
                if (light.type == scene::LightType::Spot) {
                    const LinearTexture* cookie =
                        (light.cookie >= 0 && std::size_t(light.cookie) < out.textures.size())
                            ? &out.textures[std::size_t(light.cookie)] : nullptr;
                    out.spots.push_back(SpotProfile::fromLight(light, cookie));
                    e.kind = ProfileKind::Spot;
                    e.spot = &out.spots.back();
                }
                out.points.push_back(e);
                break;
            }
            case scene::LightType::Directional: {
                out.directionals.push_back(
                    DirectionalEmitter{glm::normalize(light.direction), light.intensity * light.color, int(li)});
                break;
            }
            case scene::LightType::Area: {
                // Product Gauss-Legendre rule over the rectangle: node (i, j) at uv = (x_i, x_j) stands for
                // the emitter patch of area w_i w_j |2 halfU x 2 halfV|.
                const double area = 4.0 * glm::length(glm::cross(light.halfU, light.halfV));
                const glm::dvec3 n = glm::normalize(light.direction);
                AreaRange range{int(li), out.points.size(), 0};
                for (std::size_t j = 0; j < rule.nodes.size(); ++j) {
                    for (std::size_t i = 0; i < rule.nodes.size(); ++i) {
                        const glm::dvec2 uv(rule.nodes[i], rule.nodes[j]);
                        PointEmitter e;
                        e.position = light.position + (2.0 * uv.x - 1.0) * light.halfU + (2.0 * uv.y - 1.0) * light.halfV;
                        const double dA = rule.weights[i] * rule.weights[j] * area;
                        e.intensity = areaRadiance(light, out.textures, uv) * dA;
                        e.kind = ProfileKind::Lambertian;
                        e.normal = n;
                        e.light = int(li);
                        e.nodeWeight = rule.weights[i] * rule.weights[j];
                        out.points.push_back(e);
                        ++range.count;
                    }
                }
                out.areas.push_back(range);
                break;
            }
        }
    }
    return out;
}

}  // namespace viz::reference
