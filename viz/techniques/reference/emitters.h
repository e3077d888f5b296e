// The lights of a scene prepared for the reference, in world space and double precision:
// point-like emitters (point lights, spot lights, and the cells of area lights, each with its own
// visibility and angular profile; a cell integrates its kernel over its area, see area_cells.h) and
// directional lights.
//
// Notation: P the emitter position, s the spot direction, x a point in the medium, r = |x - P|.
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"
#include "techniques/reference/area_cells.h"
#include "techniques/reference/linear_texture.h"

namespace viz::reference {

// KHR_lights_punctual spot cone plus an optional cookie projected over the outer cone.
struct SpotProfile {
    glm::dvec3 axis{0, 0, -1};           // s, unit, the direction the light travels
    glm::dvec3 right{1, 0, 0}, up{0, 1, 0};  // light frame: x right, y up, z = s
    double cosInner = 1.0, cosOuter = 0.0;
    double scale = 1.0, offset = 0.0;    // A = clamp(cd * scale + offset, 0, 1)^2
    double tanOuter = 1.0;
    const LinearTexture* cookie = nullptr;

    static SpotProfile fromLight(const scene::Light& light, const LinearTexture* cookie);
    // A_spot for the unit direction light -> point.
    double attenuation(const glm::dvec3& dirFromLight) const;
    // A_spot * cookie (RGB) for the unit direction light -> point.
    glm::dvec3 evaluate(const glm::dvec3& dirFromLight) const;
    // Light-space [0,1]^2 coordinates of the projected cookie for a direction with z > 0.
    glm::dvec2 cookieUv(const glm::dvec3& dirFromLight) const;
};

// Builds the light frame (x right, y up, z = s) from s and world up (0,1,0), or (1,0,0) when s is
// within ~2.6 degrees of vertical.
void spotFrame(const glm::dvec3& s, glm::dvec3& right, glm::dvec3& up);

enum class ProfileKind { Isotropic, Spot, Lambertian };

// A point source: radiant intensity I(x) = intensity * profile(direction P -> x).
struct PointEmitter {
    glm::dvec3 position{0.0};
    glm::dvec3 intensity{0.0};  // point/spot: I * colour; area cell: int_cell L_e dA (RGB)
    ProfileKind kind = ProfileKind::Isotropic;
    const SpotProfile* spot = nullptr;  // kind == Spot
    glm::dvec3 normal{0.0};             // kind == Lambertian: emitter normal, profile = max(0, cos)
    int light = -1;                     // index into Scene::lights
    double nodeWeight = 1.0;            // share of the light this emitter stands for (1, or cell area / area)
    const AreaCell* cell = nullptr;     // area cells: the cell (position = its centre, for visibility)

    // profile(direction P -> x) for unit dir (RGB because of cookies).
    glm::dvec3 profile(const glm::dvec3& dirFromLight) const;
};

struct DirectionalEmitter {
    glm::dvec3 direction{0, 0, -1};  // travel direction, unit
    glm::dvec3 irradiance{0.0};      // I * colour
    int light = -1;
};

// Everything the per-pixel integrals need about the lights, built once per run.
struct PreparedLights {
    std::vector<LinearTexture> textures;  // Scene::textures decoded, same indices
    std::vector<SpotProfile> spots;       // one per spot light (PointEmitter::spot points here)
    std::vector<AreaEmitter> areaEmitters;  // one per area light (AreaCell::emitter points here)
    std::vector<AreaCell> cells;            // every area light's cells (PointEmitter::cell points here)
    std::vector<PointEmitter> points;     // point, spot, and area-light cells
    std::vector<DirectionalEmitter> directionals;
    // For each area light: its index and the range of its cells in points.
    struct AreaRange {
        int light = -1;
        std::size_t first = 0, count = 0;
    };
    std::vector<AreaRange> areas;
    int lightCount = 0;

    // areaSamples: cells per rectangle axis (areaSamples^2 cells per area light).
    static PreparedLights build(const scene::Scene& scene, int areaSamples);
    PreparedLights() = default;
    PreparedLights(const PreparedLights&) = delete;
    PreparedLights& operator=(const PreparedLights&) = delete;
    PreparedLights(PreparedLights&&) = default;
    PreparedLights& operator=(PreparedLights&&) = default;
};

// Emitted radiance L_e of an area light at rectangle coordinates uv in [0,1]^2 (uv (0,0) at
// position - halfU - halfV).
glm::dvec3 areaRadiance(const scene::Light& light, const std::vector<LinearTexture>& textures, glm::dvec2 uv);

}  // namespace viz::reference
