// The scene model shared by every technique and the reference. Geometry is flattened to world space
// (node transforms applied at load time); textures keep the bytes of the file they came from so that
// export-scene round-trips exactly.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace viz::scene {

// 8-bit RGBA texture as stored in the file. Colour textures (base colour, emission, cookie) are
// sRGB-encoded; use srgbToLinear() from scene/texture_sampling.h when sampling.
struct Texture {
    std::string name;
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba8;  // width * height * 4, row 0 = first row of the file (top)
};

struct Material {
    std::string name;
    glm::vec4 baseColorFactor{1.0f};  // linear
    int baseColorTexture = -1;        // index into Scene::textures
    glm::vec3 emissiveFactor{0.0f};   // linear
    float emissiveStrength = 1.0f;    // KHR_materials_emissive_strength
    int emissiveTexture = -1;
    bool isEmissive() const { return emissiveFactor != glm::vec3(0.0f) && emissiveStrength > 0.0f; }
};

// One triangle list in world space. normals and uvs are either empty or one per position.
struct Mesh {
    std::string name;
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec2> uvs;
    std::vector<std::uint32_t> indices;  // three per triangle
    int material = -1;                   // index into Scene::materials, -1 = default white
};

enum class LightType { Point, Spot, Directional, Area };

struct Light {
    std::string name{};  // {}: a designated initializer may leave it out (-Wmissing-field-initializers)
    LightType type = LightType::Point;
    glm::dvec3 position{0.0};        // point, spot; area: centre of the rectangle
    glm::dvec3 direction{0, 0, -1};  // unit; spot/directional: direction the light travels (node -Z);
                                     // area: the emitter's normal (it emits into this half-space)
    glm::dvec3 colour{1.0};           // linear
    double intensity = 1.0;          // KHR_lights_punctual: candela (point/spot), lux (directional)
    double innerConeAngle = 0.0;     // spot, radians
    double outerConeAngle = 0.7853981633974483;  // spot, radians
    int cookie = -1;                 // spot only: texture projected over the outer cone (light extras)

    // Area lights (a rectangle emitting L_e = emissiveFactor * emissiveStrength * emissiveTexture).
    glm::dvec3 halfU{0.0};           // half edge vectors: corners are position +- halfU +- halfV
    glm::dvec3 halfV{0.0};           // cross(halfU, halfV) is parallel to direction, either sign: the uvs
                                     // decide halfU/halfV, the winding decides direction (area_light.h)
    glm::dvec3 radiance{0.0};        // L_e without the texture, linear
    int emissionTexture = -1;        // uv (0,0) at position - halfU - halfV, u along halfU, v along halfV
    int mesh = -1;                   // the emitter's mesh in Scene::meshes
};

// Homogeneous medium, in inverse scene units; g is the Henyey-Greenstein asymmetry (0 = isotropic).
struct Medium {
    double sigma_s = 0.0;
    double sigma_a = 0.0;
    double g = 0.0;
    double sigma_t() const { return sigma_s + sigma_a; }
};

struct Camera {
    std::string name;
    glm::dvec3 position{0.0};
    glm::dvec3 forward{0, 0, -1};  // unit, the node's -Z
    glm::dvec3 up{0, 1, 0};        // unit, orthogonal to forward, the node's +Y
    double yfov = 0.8;             // radians
    double znear = 0.05;
    double zfar = 100.0;           // also the distance d of rays that hit nothing
    double aspectRatio = 0.0;      // 0: width / height of the image
};

struct Scene {
    std::string name;
    std::vector<Mesh> meshes;
    std::vector<Material> materials;
    std::vector<Texture> textures;
    std::vector<Light> lights;
    Camera camera;
    Medium medium;
    std::vector<std::string> notes;  // what the loader decided on its own, e.g. "no camera: framed the scene"
    // 0, or the owner's word that meshes, materials and textures are final: their content hash, set by
    // stampGeometry (scene_source.h). A stamped scene's bounds (scene/bounds.h) are walked and its upload
    // keyed once. Copies keep it; whoever changes a stamped scene's geometry stamps it again or zeroes it.
    std::uint64_t geometryKey = 0;
};

// Whether any of the scene's lights is an area light (the techniques sample those as VPLs).
inline bool hasAreaLight(const Scene& scene) {
    for (const Light& l : scene.lights)
        if (l.type == LightType::Area) return true;
    return false;
}

}  // namespace viz::scene
