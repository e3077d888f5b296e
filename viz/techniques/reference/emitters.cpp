#include "techniques/reference/emitters.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace viz::reference {

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
    // Reserve so that the pointers PointEmitter::spot, PointEmitter::cell and AreaCell::emitter keep stay
    // valid (moving the vectors later keeps their elements in place).
    const int n = std::max(1, areaSamples);
    std::size_t areaLights = 0;
    for (const auto& light : scene.lights) areaLights += light.type == scene::LightType::Area ? 1u : 0u;
    out.spots.reserve(scene.lights.size());
    out.areaEmitters.reserve(areaLights);
    out.cells.reserve(areaLights * std::size_t(n) * std::size_t(n));
    for (std::size_t li = 0; li < scene.lights.size(); ++li) {
        const scene::Light& light = scene.lights[li];
        switch (light.type) {
            case scene::LightType::Point:
            case scene::LightType::Spot: {
                PointEmitter e;
                e.position = light.position;
                e.intensity = light.intensity * light.colour;
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
                    DirectionalEmitter{glm::normalize(light.direction), light.intensity * light.colour, int(li)});
                break;
            }
            case scene::LightType::Area: {
                // N x N equal cells of the rectangle; each is one emitter for visibility (from its centre)
                // and integrates its kernel over its area (area_cells.h).
                out.areaEmitters.push_back(AreaEmitter::fromLight(light, int(li), out.textures));
                const AreaEmitter& emitter = out.areaEmitters.back();
                AreaRange range{int(li), out.points.size(), 0};
                for (int j = 0; j < n; ++j) {
                    for (int i = 0; i < n; ++i) {
                        AreaCell cell;
                        cell.emitter = &emitter;
                        cell.uv0 = glm::dvec2(double(i), double(j)) / double(n);
                        cell.uv1 = glm::dvec2(double(i + 1), double(j + 1)) / double(n);
                        cell.farNodes = leafNodes(emitter, cell.uv0, cell.uv1, kLeafOrderFar);
                        cell.nearNodes = leafNodes(emitter, cell.uv0, cell.uv1, kLeafOrderNear);
                        out.cells.push_back(std::move(cell));
                        const AreaCell& stored = out.cells.back();
                        PointEmitter e;
                        e.position = emitter.position(0.5 * (stored.uv0 + stored.uv1));
                        for (const CellNode& node : stored.farNodes) e.intensity += node.weight;
                        e.kind = ProfileKind::Lambertian;
                        e.normal = emitter.normal;
                        e.light = int(li);
                        e.nodeWeight = 1.0 / (double(n) * double(n));
                        e.cell = &stored;
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
