#include "render/gpu_scene.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <map>

#include "core/error.h"

namespace viz::render {

namespace {

// ---- texture array packing ----
// Each distinct texture index used by a material gets one layer; the array is as large as the largest
// texture, and smaller ones use the [0, w) x [0, h) corner of their layer (shaders clamp to it).
struct TexturePacking {
    std::map<int, int> layerOf;  // scene texture index -> layer
    int width = 1, height = 1;
};

TexturePacking packTextures(const scene::Scene& scene) {
    TexturePacking packing;
    auto use = [&](int texture) {
        if (texture < 0) return;
        VIZ_CHECK(texture < static_cast<int>(scene.textures.size()), "material texture index out of range");
        if (packing.layerOf.count(texture)) return;
        const int layer = static_cast<int>(packing.layerOf.size());
        packing.layerOf[texture] = layer;
        const auto& t = scene.textures[static_cast<std::size_t>(texture)];
        packing.width = std::max(packing.width, t.width);
        packing.height = std::max(packing.height, t.height);
    };
    for (const auto& m : scene.materials) {
        use(m.baseColorTexture);
        use(m.emissiveTexture);
    }
    return packing;
}

gl::Texture uploadTextures(const scene::Scene& scene, const TexturePacking& packing) {
    const int layers = std::max(1, static_cast<int>(packing.layerOf.size()));
    // Every layer is as large as the largest texture: refuse sets where that wastes absurd memory.
    const double bytes = 4.0 * packing.width * packing.height * layers;
    if (bytes > 512.0 * 1024 * 1024) {
        throw InputError("material textures need " + std::to_string(int(bytes / (1024 * 1024))) +
                         " MB as one array of " + std::to_string(layers) + " layers of " +
                         std::to_string(packing.width) + "x" + std::to_string(packing.height) +
                         " (the largest texture); the limit is 512 MB");
    }
    auto array = gl::Texture::create({.target = GL_TEXTURE_2D_ARRAY,
                                      .format = GL_RGBA8,  // sRGB bytes, decoded in the shader
                                      .size = {packing.width, packing.height, layers},
                                      .label = "render.material_textures"});
    // Shaders filter by hand with texelFetch (to match scene::sampleLinearRgb exactly), so the texture's
    // own filter only matters to viewers.
    array.setFilter(GL_NEAREST, GL_NEAREST);
    array.setWrap(GL_CLAMP_TO_EDGE);
    for (const auto& [texture, layer] : packing.layerOf) {
        const auto& t = scene.textures[static_cast<std::size_t>(texture)];
        VIZ_CHECK(t.rgba8.size() == static_cast<std::size_t>(t.width) * static_cast<std::size_t>(t.height) * 4,
                  "texture '" + t.name + "' has the wrong byte count");
        // Row 0 of the file (the top, v = 0) goes to texel row 0, so texel y = v * height.
        array.uploadRegion({0, 0, layer}, {t.width, t.height, 1}, GL_RGBA, GL_UNSIGNED_BYTE, t.rgba8.data());
    }
    return array;
}

std::vector<GpuMaterialCpu> buildMaterials(const scene::Scene& scene, const TexturePacking& packing) {
    std::vector<GpuMaterialCpu> out;
    auto layerSize = [&](int texture) {
        if (texture < 0) return glm::vec2(1.0f);
        const auto& t = scene.textures[static_cast<std::size_t>(texture)];
        return glm::vec2(float(t.width), float(t.height));
    };
    auto layer = [&](int texture) { return texture < 0 ? -1 : packing.layerOf.at(texture); };
    for (const auto& m : scene.materials) {
        GpuMaterialCpu g{};
        g.baseColour = m.baseColorFactor;
        g.emissive = m.isEmissive() ? glm::vec4(m.emissiveFactor * m.emissiveStrength, 0.0f) : glm::vec4(0.0f);
        g.layers = glm::ivec4(layer(m.baseColorTexture), m.isEmissive() ? layer(m.emissiveTexture) : -1, 0, 0);
        g.layerSize = glm::vec4(layerSize(m.baseColorTexture), layerSize(m.emissiveTexture));
        out.push_back(g);
    }
    // The default material (white, not emissive) for meshes with material -1, always last.
    GpuMaterialCpu white{};
    white.baseColour = glm::vec4(1.0f);
    white.layers = glm::ivec4(-1, -1, 0, 0);
    white.layerSize = glm::vec4(1.0f);
    out.push_back(white);
    return out;
}

// ---- geometry ----
struct Geometry {
    std::vector<GpuVertex> vertices;
    std::vector<std::uint32_t> indices;
};

Geometry buildGeometry(const scene::Scene& scene) {
    // Emitter meshes shade with the light's normal (the emitting side), exactly flat.
    std::map<int, glm::vec3> emitterNormal;
    for (const auto& light : scene.lights) {
        if (light.type == scene::LightType::Area && light.mesh >= 0) {
            emitterNormal[light.mesh] = glm::vec3(light.direction);
        }
    }
    const auto defaultMaterial = static_cast<std::uint32_t>(scene.materials.size());
    Geometry g;
    for (std::size_t mi = 0; mi < scene.meshes.size(); ++mi) {
        const auto& mesh = scene.meshes[mi];
        VIZ_CHECK(mesh.indices.size() % 3 == 0, "mesh '" + mesh.name + "' index count is not a multiple of 3");
        const std::uint32_t material =
            mesh.material < 0 ? defaultMaterial : static_cast<std::uint32_t>(mesh.material);
        const bool hasNormals = mesh.normals.size() == mesh.positions.size();
        const bool hasUvs = mesh.uvs.size() == mesh.positions.size();
        const auto emitter = emitterNormal.find(static_cast<int>(mi));
        auto vertex = [&](std::uint32_t i, glm::vec3 normal) {
            return GpuVertex{mesh.positions[i], normal, hasUvs ? mesh.uvs[i] : glm::vec2(0.0f), material};
        };
        if (hasNormals || emitter != emitterNormal.end()) {
            // Shared vertices, indexed as in the mesh.
            const auto base = static_cast<std::uint32_t>(g.vertices.size());
            for (std::uint32_t i = 0; i < mesh.positions.size(); ++i) {
                const glm::vec3 n =
                    emitter != emitterNormal.end() ? emitter->second : glm::normalize(mesh.normals[i]);
                g.vertices.push_back(vertex(i, n));
            }
            for (auto i : mesh.indices) {
                VIZ_CHECK(i < mesh.positions.size(), "mesh '" + mesh.name + "' index out of range");
                g.indices.push_back(base + i);
            }
        } else {
            // No normals: three vertices per triangle carrying the flat geometric normal (counter-
            // clockwise winding faces it; shaders flip normals toward the eye anyway).
            for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
                const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
                VIZ_CHECK(std::max({i0, i1, i2}) < mesh.positions.size(),
                          "mesh '" + mesh.name + "' index out of range");
                const glm::dvec3 p0(mesh.positions[i0]), p1(mesh.positions[i1]), p2(mesh.positions[i2]);
                const glm::dvec3 c = glm::cross(p1 - p0, p2 - p0);
                const double len = glm::length(c);
                const glm::vec3 n = len > 0.0 ? glm::vec3(c / len) : glm::vec3(0, 0, 1);
                for (auto i : {i0, i1, i2}) {
                    g.indices.push_back(static_cast<std::uint32_t>(g.vertices.size()));
                    g.vertices.push_back(vertex(i, n));
                }
            }
        }
    }
    return g;
}

}  // namespace

GpuScene::GpuScene(const scene::Scene& scene) : mBounds(scene::sceneBounds(scene)) {
    const TexturePacking packing = packTextures(scene);
    mTextures = uploadTextures(scene, packing);

    const auto materials = buildMaterials(scene, packing);
    mMaterialCount = static_cast<int>(materials.size());
    mMaterials = gl::Buffer::create({.bytes = materials.size() * sizeof(GpuMaterialCpu),
                                     .data = materials.data(),
                                     .label = "render.materials"});

    Geometry geometry = buildGeometry(scene);
    mIndexCount = static_cast<int>(geometry.indices.size());
    // Never create zero-byte buffers: an empty scene draws nothing but stays valid.
    if (geometry.vertices.empty()) geometry.vertices.push_back(GpuVertex{});
    if (geometry.indices.empty()) geometry.indices.push_back(0);
    mVertices = gl::Buffer::create({.bytes = geometry.vertices.size() * sizeof(GpuVertex),
                                    .data = geometry.vertices.data(),
                                    .label = "render.vertices"});
    mIndices = gl::Buffer::create({.bytes = geometry.indices.size() * sizeof(std::uint32_t),
                                   .data = geometry.indices.data(),
                                   .label = "render.indices"});

    mVao = gl::VertexArray::create("render.scene_vao");
    mVao.vertexBuffer(0, mVertices, 0, sizeof(GpuVertex));
    mVao.elementBuffer(mIndices);
    mVao.attribute(kAttribPosition, 0, 3, GL_FLOAT, offsetof(GpuVertex, position));
    mVao.attribute(kAttribNormal, 0, 3, GL_FLOAT, offsetof(GpuVertex, normal));
    mVao.attribute(kAttribUv, 0, 2, GL_FLOAT, offsetof(GpuVertex, uv));
    mVao.attributeInt(kAttribMaterial, 0, 1, GL_UNSIGNED_INT, offsetof(GpuVertex, material));
}

void GpuScene::draw() const {
    if (mIndexCount == 0) return;
    mVao.bind();
    glDrawElements(GL_TRIANGLES, mIndexCount, GL_UNSIGNED_INT, nullptr);
}

void GpuScene::bindMaterials() const {
    mMaterials.bindBase(GL_SHADER_STORAGE_BUFFER, hd::kBindingMaterials);
    mTextures.bindUnit(hd::kUnitMaterialTextures);
}

}  // namespace viz::render
