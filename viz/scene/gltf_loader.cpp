#include "scene/gltf_loader.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <set>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <tiny_gltf.h>

#include "core/error.h"
#include "scene/area_light.h"
#include "scene/default_lighting.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_input.h"
#include "scene/gltf_mesh_fixes.h"
#include "scene/validate.h"

namespace viz::scene {
namespace {

constexpr double kDefaultZfar = 1000.0;  // glTF infinite projection: zfar absent
constexpr int kMaxNodeDepth = 256;       // deeper trees are refused (the visit recurses)

using gltf::frameScene;
using gltf::quoteValue;
using gltf::repairNormals;
using gltf::toRgba8;

// ---- helpers ----

bool finite(double v) { return std::isfinite(v); }

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof(text), "%.6g", v);
    return text;
}

// Node-local matrix: 'matrix' (column-major) or T * R * S. The values were checked finite.
glm::dmat4 localMatrix(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::dmat4 m(1.0);
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) m[c][r] = node.matrix[std::size_t(c * 4 + r)];
        }
        return m;
    }
    glm::dmat4 m(1.0);
    if (node.translation.size() == 3) {
        m = glm::translate(m, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    }
    if (node.rotation.size() == 4) {
        // glTF quaternions are (x, y, z, w); glm's constructor takes (w, x, y, z).
        const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        m = m * glm::mat4_cast(glm::normalize(q));
    }
    if (node.scale.size() == 3) m = glm::scale(m, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

// Unit vector; left untouched when already unit to the last bits, so that exported directions
// load back bit for bit.
glm::dvec3 unitOrSelf(const glm::dvec3& v) {
    const double len = glm::length(v);
    return std::abs(len - 1.0) < 1e-14 ? v : v / len;
}

// ---- the loader ----

class Loader {
public:
    Loader(const tinygltf::Model& model, gltf::TextureUse use, const std::string& file, const LoadOptions& options)
        : mModel(model), mUse(std::move(use)), mFile(file), mOptions(options),
          mRead(model, "glTF " + quoteValue(file) + ": ") {}

    Scene load() {
        checkNodeForest();
        loadTextures();
        loadMaterials();
        const int sceneIndex = mModel.defaultScene >= 0 ? mModel.defaultScene : 0;
        std::vector<int> roots;
        if (!mModel.scenes.empty()) {
            if (std::size_t(sceneIndex) >= mModel.scenes.size()) mRead.fail("default scene does not exist");
            roots = mModel.scenes[std::size_t(sceneIndex)].nodes;
            mScene.name = mModel.scenes[std::size_t(sceneIndex)].name;
        } else {
            // No scenes: every node that is nobody's child is a root.
            for (int n = 0; n < int(mModel.nodes.size()); ++n) {
                if (mParent[std::size_t(n)] < 0) roots.push_back(n);
            }
        }
        if (mScene.name.empty()) mScene.name = std::filesystem::path(mFile).stem().string();
        for (int root : roots) checkNode(root, "scene root");
        for (int root : roots) budget(root, 0);
        for (int root : roots) visit(root, glm::dmat4(1.0), 0);
        loadAreaLights();
        noteUnusedLights();
        if (!mHaveCamera) {
            mScene.camera = frameScene(mScene);
            mScene.notes.push_back("no camera: framed the scene");
        }
        loadMedium(sceneIndex);
        if (mScene.lights.empty() && mOptions.defaultLight && !mScene.meshes.empty()) {
            mScene.lights.push_back(defaultSpotLight(mScene));
            mScene.notes.push_back("no light in " + quoteValue(mFile) + ": added a default spot light above the model (--no-default-light to refuse)");
        }
        return std::move(mScene);
    }

private:
    void checkNode(int index, const std::string& who) const {
        if (index < 0 || std::size_t(index) >= mModel.nodes.size()) {
            mRead.fail(who + " refers to node " + std::to_string(index) + ", which does not exist");
        }
    }

    // glTF nodes form a forest: every child exists, no node has two parents (or is a scene root and a
    // child), and no node is its own ancestor. Without this a file of a few KB could make the visit
    // below take 2^63 steps.
    void checkNodeForest() {
        const std::size_t n = mModel.nodes.size();
        mParent.assign(n, -1);
        for (std::size_t p = 0; p < n; ++p) {
            for (int child : mModel.nodes[p].children) {
                checkNode(child, "node " + std::to_string(p));
                int& parent = mParent[std::size_t(child)];
                if (parent >= 0) {
                    mRead.fail("node " + std::to_string(child) + " is a child of both node " + std::to_string(parent) +
                               " and node " + std::to_string(p) + " (glTF nodes must form a tree)");
                }
                parent = int(p);
            }
        }
        for (std::size_t s = 0; s < mModel.scenes.size(); ++s) {
            std::set<int> listed;
            for (int root : mModel.scenes[s].nodes) {
                checkNode(root, "scene " + std::to_string(s));
                if (!listed.insert(root).second) {
                    mRead.fail("scene " + std::to_string(s) + " lists node " + std::to_string(root) + " twice");
                }
                if (mParent[std::size_t(root)] >= 0) {
                    mRead.fail("node " + std::to_string(root) + " is a root of scene " + std::to_string(s) +
                               " and a child of node " + std::to_string(mParent[std::size_t(root)]));
                }
            }
        }
        // With one parent each, a cycle is a parent chain that never reaches a root.
        std::vector<char> state(n, 0);  // 0 unknown, 1 on the current chain, 2 reaches a root
        for (std::size_t start = 0; start < n; ++start) {
            std::vector<std::size_t> chain;
            std::size_t at = start;
            while (state[at] == 0) {
                state[at] = 1;
                chain.push_back(at);
                if (mParent[at] < 0) break;
                at = std::size_t(mParent[at]);
            }
            if (state[at] == 1 && mParent[at] >= 0) {
                mRead.fail("node " + std::to_string(at) + " is its own ancestor (the node hierarchy has a cycle)");
            }
            for (std::size_t c : chain) state[c] = 2;
        }
    }

    // Counts what the scene's tree will instance before any vertex is read (LoadLimits).
    void budget(int nodeIndex, int depth) {
        if (depth > kMaxNodeDepth) mRead.fail("node hierarchy is deeper than " + std::to_string(kMaxNodeDepth));
        const tinygltf::Node& node = mModel.nodes[std::size_t(nodeIndex)];
        if (node.mesh >= 0 && std::size_t(node.mesh) < mModel.meshes.size()) {
            for (const tinygltf::Primitive& prim : mModel.meshes[std::size_t(node.mesh)].primitives) {
                const auto pos = prim.attributes.find("POSITION");
                if (pos == prim.attributes.end()) continue;
                const std::uint64_t vertices = mRead.count(pos->second, "POSITION");
                const std::uint64_t corners = prim.indices >= 0 ? mRead.count(prim.indices, "indices") : vertices;
                mInstances += 1;
                mVertices += vertices;
                mTriangles += corners / 3;
            }
            if (mInstances > LoadLimits::kMaxMeshInstances || mVertices > LoadLimits::kMaxVertices ||
                mTriangles > LoadLimits::kMaxTriangles) {
                mRead.fail("the scene places more than the limits allow (at most " +
                           std::to_string(LoadLimits::kMaxMeshInstances) + " mesh primitives, " +
                           std::to_string(LoadLimits::kMaxTriangles) + " triangles, " +
                           std::to_string(LoadLimits::kMaxVertices) + " vertices after instancing; reached " +
                           std::to_string(mInstances) + ", " + std::to_string(mTriangles) + ", " +
                           std::to_string(mVertices) + ")");
            }
        }
        for (int child : node.children) budget(child, depth + 1);
    }

    // The textures something draws, in file order; the others are left out (with one note) and map to -1.
    void loadTextures() {
        mTextureSlot.assign(mModel.textures.size(), -1);
        for (std::size_t t = 0; t < mModel.textures.size(); ++t) {
            if (t >= mUse.textures.size() || !mUse.textures[t]) continue;
            const tinygltf::Texture& gt = mModel.textures[t];
            if (gt.source < 0 || std::size_t(gt.source) >= mModel.images.size()) {
                mRead.fail("texture " + std::to_string(t) + " has no valid image source");
            }
            const tinygltf::Image& image = mModel.images[std::size_t(gt.source)];
            const std::string who = "image " + std::to_string(gt.source) +
                                    (image.uri.empty() || image.uri.rfind("data:", 0) == 0 ? "" : " (" + quoteValue(image.uri) + ")");
            const bool sized = image.width > 0 && image.height > 0 && image.component >= 1 && image.component <= 4 &&
                               (image.bits == 8 || image.bits == 16);
            if (image.image.empty() || !sized) mRead.fail(who + " could not be decoded");
            const std::uint64_t bytes = std::uint64_t(image.width) * std::uint64_t(image.height) *
                                        std::uint64_t(image.component) * std::uint64_t(image.bits / 8);
            if (bytes != image.image.size()) mRead.fail(who + ": decoded size does not match its width and height");
            Texture tex;
            tex.name = !gt.name.empty() ? gt.name : image.name;
            tex.width = image.width;
            tex.height = image.height;
            tex.rgba8 = toRgba8(image);
            mTextureSlot[t] = int(mScene.textures.size());
            mScene.textures.push_back(std::move(tex));
        }
        const std::string note = mUse.note();
        if (!note.empty()) mScene.notes.push_back(note);
    }

    int textureIndex(int index, const std::string& who) const {
        if (index < -1 || index >= int(mModel.textures.size())) {
            mRead.fail(who + " refers to missing texture " + std::to_string(index));
        }
        if (index < 0) return -1;
        const int slot = mTextureSlot[std::size_t(index)];
        // Only when the raw JSON value was not the integer tinygltf read (e.g. 2^32 taken as 0).
        if (slot < 0) mRead.fail(who + ": texture index " + std::to_string(index) + " is not a plain integer in range");
        return slot;
    }

    // A factor's components: finite and in [0, hi] (glTF allows [0, 1] for colours).
    void checkFactor(const std::vector<double>& f, const std::string& who, double hi) const {
        for (std::size_t i = 0; i < f.size(); ++i) {
            if (!finite(f[i]) || f[i] < 0.0 || f[i] > hi) {
                mRead.fail(who + "[" + std::to_string(i) + "] = " + number(f[i]) + " is outside [0, " + number(hi) + "]");
            }
        }
    }

    void loadMaterials() {
        for (std::size_t m = 0; m < mModel.materials.size(); ++m) {
            const tinygltf::Material& gm = mModel.materials[m];
            const std::string who = "material " + std::to_string(m);
            Material mat;
            mat.name = gm.name;
            const auto& f = gm.pbrMetallicRoughness.baseColorFactor;
            checkFactor(f, who + " baseColorFactor", 1.0);
            if (f.size() == 4) mat.baseColorFactor = glm::vec4(float(f[0]), float(f[1]), float(f[2]), float(f[3]));
            mat.baseColorTexture = textureIndex(gm.pbrMetallicRoughness.baseColorTexture.index, who);
            checkFactor(gm.emissiveFactor, who + " emissiveFactor", 1.0);
            if (gm.emissiveFactor.size() == 3) {
                mat.emissiveFactor = glm::vec3(float(gm.emissiveFactor[0]), float(gm.emissiveFactor[1]),
                                               float(gm.emissiveFactor[2]));
            }
            mat.emissiveTexture = textureIndex(gm.emissiveTexture.index, who);
            const auto strength = gm.extensions.find("KHR_materials_emissive_strength");
            if (strength != gm.extensions.end()) {
                const double v = numberOr(strength->second, "emissiveStrength", 1.0);
                if (!finite(v) || v < 0.0 || v > LoadLimits::kMaxRadiance) {
                    mRead.fail(who + " emissiveStrength " + number(v) + " is outside [0, " + number(LoadLimits::kMaxRadiance) + "]");
                }
                mat.emissiveStrength = float(v);
            }
            if (gm.pbrMetallicRoughness.baseColorTexture.texCoord != 0 || gm.emissiveTexture.texCoord != 0) {
                mScene.notes.push_back(who + ": only TEXCOORD_0 is used");
            }
            mScene.materials.push_back(std::move(mat));
        }
    }

    static double numberOr(const tinygltf::Value& obj, const char* key, double fallback) {
        if (!obj.IsObject() || !obj.Has(key)) return fallback;
        const tinygltf::Value& v = obj.Get(key);
        return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
    }

    void checkTransform(const tinygltf::Node& node, int nodeIndex) const {
        const std::string who = "node " + std::to_string(nodeIndex);
        auto all = [&](const std::vector<double>& v, const char* what) {
            for (double x : v) {
                if (!finite(x) || std::abs(x) > LoadLimits::kMaxCoordinate) {
                    mRead.fail(who + " " + what + " has a value " + number(x) + " that is not finite or beyond 1e15");
                }
            }
        };
        all(node.matrix, "matrix");
        all(node.translation, "translation");
        all(node.rotation, "rotation");
        all(node.scale, "scale");
        if (!node.matrix.empty() && node.matrix.size() != 16) mRead.fail(who + " matrix must have 16 numbers");
        if (node.rotation.size() == 4) {
            const double n2 = node.rotation[0] * node.rotation[0] + node.rotation[1] * node.rotation[1] +
                              node.rotation[2] * node.rotation[2] + node.rotation[3] * node.rotation[3];
            if (!(n2 > 1e-12)) mRead.fail(who + " rotation is a zero quaternion");
        }
    }

    void visit(int nodeIndex, const glm::dmat4& parent, int depth) {
        const tinygltf::Node& node = mModel.nodes[std::size_t(nodeIndex)];
        checkTransform(node, nodeIndex);
        const glm::dmat4 world = parent * localMatrix(node);
        if (node.mesh >= 0) loadMesh(node.mesh, world, nodeIndex);
        if (node.camera >= 0 && !mHaveCamera) loadCamera(node.camera, world);
        const auto light = node.extensions.find("KHR_lights_punctual");
        if (light != node.extensions.end()) {
            const double index = numberOr(light->second, "light", -1.0);
            if (!(index >= 0.0 && index < double(mModel.lights.size()) && index == std::floor(index))) {
                mRead.fail("node " + std::to_string(nodeIndex) + ": KHR_lights_punctual light " + number(index) + " does not exist");
            }
            loadLight(int(index), world, node.name);
        }
        for (int child : node.children) visit(child, world, depth + 1);
    }

    void loadMesh(int meshIndex, const glm::dmat4& world, int nodeIndex) {
        if (std::size_t(meshIndex) >= mModel.meshes.size()) mRead.fail("mesh " + std::to_string(meshIndex) + " does not exist");
        const tinygltf::Mesh& gm = mModel.meshes[std::size_t(meshIndex)];
        const bool identity = world == glm::dmat4(1.0);
        const double det = glm::determinant(glm::dmat3(world));
        if (!(std::abs(det) > 0.0) || !std::isfinite(det)) {
            mScene.notes.push_back("node " + std::to_string(nodeIndex) + " has a singular transform (a scale of 0): its mesh is skipped");
            return;
        }
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
        // A mirroring transform turns counter-clockwise into clockwise; swap two indices to undo it.
        const bool mirrored = det < 0.0;
        for (std::size_t p = 0; p < gm.primitives.size(); ++p) {
            const tinygltf::Primitive& prim = gm.primitives[p];
            const std::string who = "mesh " + std::to_string(meshIndex) + (gm.name.empty() ? "" : " " + quoteValue(gm.name)) +
                                    " primitive " + std::to_string(p);
            const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
            if (mode != TINYGLTF_MODE_TRIANGLES) {
                mScene.notes.push_back(who + ": mode " + std::to_string(mode) + " is not TRIANGLES, skipped");
                continue;
            }
            const auto pos = prim.attributes.find("POSITION");
            if (pos == prim.attributes.end()) mRead.fail(who + " has no POSITION");
            Mesh mesh;
            mesh.name = gm.name.empty() ? "mesh" + std::to_string(meshIndex) : gm.name;
            if (gm.primitives.size() > 1) mesh.name += "." + std::to_string(p);
            mesh.positions = mRead.readVec3Float(pos->second, who + " POSITION");
            for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
                const glm::vec3& q = mesh.positions[v];
                if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z)) {
                    mRead.fail(who + ": vertex " + std::to_string(v) + " is NaN or Inf");
                }
            }
            const auto nrm = prim.attributes.find("NORMAL");
            if (nrm != prim.attributes.end()) mesh.normals = mRead.readVec3Float(nrm->second, who + " NORMAL");
            const auto uv = prim.attributes.find("TEXCOORD_0");
            if (uv != prim.attributes.end()) mesh.uvs = mRead.readUv(uv->second, who + " TEXCOORD_0");
            if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) {
                mRead.fail(who + ": NORMAL and POSITION counts differ");
            }
            if (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()) {
                mRead.fail(who + ": TEXCOORD_0 and POSITION counts differ");
            }
            for (std::size_t v = 0; v < mesh.uvs.size(); ++v) {
                if (!std::isfinite(mesh.uvs[v].x) || !std::isfinite(mesh.uvs[v].y)) {
                    mRead.fail(who + ": TEXCOORD_0 " + std::to_string(v) + " is NaN or Inf");
                }
            }
            if (prim.indices >= 0) {
                mesh.indices = mRead.readIndices(prim.indices, who + " indices");
                for (std::uint32_t i : mesh.indices) {
                    if (i >= mesh.positions.size()) {
                        mRead.fail(who + ": index " + std::to_string(i) + " is out of range (" +
                                   std::to_string(mesh.positions.size()) + " vertices)");
                    }
                }
            } else {
                mesh.indices.resize(mesh.positions.size());
                for (std::size_t i = 0; i < mesh.indices.size(); ++i) mesh.indices[i] = std::uint32_t(i);
            }
            mesh.indices.resize(mesh.indices.size() - mesh.indices.size() % 3);
            if (prim.material >= int(mModel.materials.size())) mRead.fail(who + " refers to a missing material");
            mesh.material = prim.material;
            if (const std::size_t fixed = repairNormals(mesh)) {
                mScene.notes.push_back(who + ": " + std::to_string(fixed) + " zero-length normal" + (fixed > 1 ? "s" : "") +
                                       " replaced by the triangles' normal");
            }

            if (!identity) {
                for (glm::vec3& q : mesh.positions) q = glm::vec3(world * glm::dvec4(glm::dvec3(q), 1.0));
                for (glm::vec3& n : mesh.normals) {
                    const glm::dvec3 t = normalMatrix * glm::dvec3(n);
                    const double len = glm::length(t);
                    n = len > 0.0 && std::isfinite(len) ? glm::vec3(t / len) : n;
                }
                if (mirrored) {
                    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
                }
            }
            for (const glm::vec3& q : mesh.positions) {
                if (!(std::abs(q.x) <= LoadLimits::kMaxCoordinate && std::abs(q.y) <= LoadLimits::kMaxCoordinate &&
                      std::abs(q.z) <= LoadLimits::kMaxCoordinate)) {
                    mRead.fail(who + ": a vertex lies at (" + number(q.x) + ", " + number(q.y) + ", " + number(q.z) +
                               ") after its node's transform, beyond the 1e15 limit");
                }
            }
            mScene.meshes.push_back(std::move(mesh));
        }
    }

    void loadCamera(int cameraIndex, const glm::dmat4& world) {
        if (std::size_t(cameraIndex) >= mModel.cameras.size()) mRead.fail("camera " + std::to_string(cameraIndex) + " does not exist");
        const tinygltf::Camera& gc = mModel.cameras[std::size_t(cameraIndex)];
        if (gc.type != "perspective") {
            mScene.notes.push_back("camera " + std::to_string(cameraIndex) + " is not perspective, skipped");
            return;
        }
        Camera cam;
        cam.name = gc.name;
        cam.position = glm::dvec3(world[3]);
        // The camera looks down its node's -Z with +Y up; re-orthogonalise only when the matrix shears.
        cam.forward = unitOrSelf(-glm::dvec3(world[2]));
        glm::dvec3 up = glm::dvec3(world[1]);
        if (std::abs(glm::dot(up, cam.forward)) > 1e-12 * glm::length(up)) {
            up -= glm::dot(up, cam.forward) * cam.forward;
        }
        cam.up = unitOrSelf(up);
        cam.yfov = gc.perspective.yfov;
        cam.znear = gc.perspective.znear;
        cam.zfar = gc.perspective.zfar > 0.0 ? gc.perspective.zfar : kDefaultZfar;
        cam.aspectRatio = gc.perspective.aspectRatio > 0.0 ? gc.perspective.aspectRatio : 0.0;
        mScene.camera = cam;
        mHaveCamera = true;
    }

    void loadLight(int lightIndex, const glm::dmat4& world, const std::string& nodeName) {
        const tinygltf::Light& gl = mModel.lights[std::size_t(lightIndex)];
        const std::string who = "light " + std::to_string(lightIndex);
        mUsedLights.insert(lightIndex);
        Light light;
        light.name = !gl.name.empty() ? gl.name : nodeName;
        if (gl.type == "point") {
            light.type = LightType::Point;
        } else if (gl.type == "spot") {
            light.type = LightType::Spot;
            light.innerConeAngle = gl.spot.innerConeAngle;
            light.outerConeAngle = gl.spot.outerConeAngle;
        } else if (gl.type == "directional") {
            light.type = LightType::Directional;
        } else {
            mRead.fail(who + " has unknown type " + quoteValue(gl.type));
        }
        light.position = glm::dvec3(world[3]);
        light.direction = unitOrSelf(-glm::dvec3(world[2]));
        if (gl.color.size() == 3) light.colour = glm::dvec3(gl.color[0], gl.color[1], gl.color[2]);
        light.intensity = gl.intensity;
        for (int c = 0; c < 3; ++c) {
            if (!finite(light.colour[c]) || light.colour[c] < 0.0) {
                mRead.fail(who + " color[" + std::to_string(c) + "] = " + number(light.colour[c]) + " must be finite and >= 0");
            }
        }
        if (!finite(light.intensity) || light.intensity < 0.0) {
            mRead.fail(who + " intensity " + number(light.intensity) + " must be finite and >= 0");
        }
        const double peak = light.intensity * std::max({light.colour.x, light.colour.y, light.colour.z});
        if (peak > LoadLimits::kMaxRadiance) {
            mRead.fail(who + " intensity x colour = " + number(peak) + " is over the limit of 1e20 (GPU floats overflow)");
        }
        if (gl.extras.IsObject()) {
            for (const std::string& key : gl.extras.Keys()) {
                if (key != "cookie") mScene.notes.push_back(who + ": extras key " + quoteValue(key) + " ignored (known: cookie)");
            }
        }
        if (gl.extras.IsObject() && gl.extras.Has("cookie")) {
            const tinygltf::Value& cookie = gl.extras.Get("cookie");
            if (!cookie.IsInt()) mRead.fail(who + ": extras.cookie must be a texture index");
            if (light.type != LightType::Spot) mRead.fail(who + ": only spot lights can have a cookie");
            light.cookie = textureIndex(cookie.GetNumberAsInt(), who + " cookie");
        }
        mScene.lights.push_back(light);
    }

    // Area lights after the punctual ones, in mesh order; an emissive mesh that is no planar
    // rectangle still glows on the surface but lights nothing.
    void loadAreaLights() {
        for (int m = 0; m < int(mScene.meshes.size()); ++m) {
            const Mesh& mesh = mScene.meshes[std::size_t(m)];
            if (mesh.material < 0 || !mScene.materials[std::size_t(mesh.material)].isEmissive()) continue;
            try {
                mScene.lights.push_back(areaLightFromMesh(mScene, m));
            } catch (const InputError& e) {
                ++mGlowOnly;
                if (mGlowOnly <= 3) {
                    mScene.notes.push_back(std::string(e.what()) + ": it shades as an emissive surface and casts no light");
                } else if (mGlowOnly == 4) {
                    mScene.notes.push_back("more emissive meshes are not planar rectangles (notes left out)");
                }
            }
        }
    }

    void noteUnusedLights() {
        for (std::size_t l = 0; l < mModel.lights.size(); ++l) {
            if (mUsedLights.count(int(l))) continue;
            const std::string name = mModel.lights[l].name.empty() ? "" : " " + quoteValue(mModel.lights[l].name);
            const std::string what = "KHR_lights_punctual light " + std::to_string(l) + name +
                                     " is not used by any node of the scene";
            if (mScene.lights.empty() && !mOptions.defaultLight) mRead.fail(what + ", so the scene has no light");
            mScene.notes.push_back(what + ": ignored");
        }
    }

    void loadMedium(int sceneIndex) {
        const tinygltf::Value* medium = nullptr;
        if (std::size_t(sceneIndex) < mModel.scenes.size()) {
            const tinygltf::Value& extras = mModel.scenes[std::size_t(sceneIndex)].extras;
            if (extras.IsObject() && extras.Has("medium")) medium = &extras.Get("medium");
        }
        if (!medium) {
            mScene.medium = scaleAwareMedium(mScene);
            mScene.notes.push_back("no medium in the scene's extras: sigma_s = " + number(mScene.medium.sigma_s) +
                                   " (optical depth 0.5 across the model's bounding box), sigma_a = 0, g = 0");
            return;
        }
        if (!medium->IsObject()) mRead.fail("scene extras.medium must be an object");
        static const char* kKeys[] = {"sigma_s", "sigma_a", "g"};
        for (const std::string& key : medium->Keys()) {
            if (std::find(std::begin(kKeys), std::end(kKeys), key) == std::end(kKeys)) {
                mScene.notes.push_back("scene extras.medium: unknown key " + quoteValue(key) + " ignored (known: sigma_s, sigma_a, g)");
            }
        }
        const double defaults[] = {0.05, 0.0, 0.0};
        double values[3];
        for (int k = 0; k < 3; ++k) {
            values[k] = defaults[k];
            if (!medium->Has(kKeys[k])) continue;
            const tinygltf::Value& v = medium->Get(kKeys[k]);
            if (!v.IsNumber()) {
                mScene.notes.push_back(std::string("scene extras.medium.") + kKeys[k] + " is not a number: using " + number(defaults[k]));
                continue;
            }
            values[k] = v.GetNumberAsDouble();
        }
        for (int k = 0; k < 2; ++k) {
            if (!finite(values[k]) || values[k] < 0.0 || values[k] > LoadLimits::kMaxSigma) {
                mRead.fail(std::string("scene extras.medium.") + kKeys[k] + " = " + number(values[k]) + " is outside [0, 1e12]");
            }
        }
        mScene.medium = Medium{values[0], values[1], values[2]};
    }

    const tinygltf::Model& mModel;
    gltf::TextureUse mUse;
    std::vector<int> mTextureSlot;  // glTF texture -> index in mScene.textures, -1 when not loaded
    std::string mFile;
    LoadOptions mOptions;
    gltf::AccessorReader mRead;
    Scene mScene;
    bool mHaveCamera = false;
    std::vector<int> mParent;
    std::set<int> mUsedLights;
    int mGlowOnly = 0;
    std::uint64_t mInstances = 0, mVertices = 0, mTriangles = 0;
};

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

}  // namespace

Scene loadGltfFromMemory(const std::vector<unsigned char>& bytes, const std::string& file, const std::string& baseDir,
                         bool binary, const LoadOptions& options) {
    tinygltf::Model model;
    gltf::TextureUse use = gltf::parseModel(bytes, file, baseDir, binary, model);
    Scene scene;
    try {
        scene = Loader(model, std::move(use), file, options).load();
    } catch (const std::bad_alloc&) {
        throw InputError("glTF " + quoteValue(file) + ": too large to load (out of memory)");
    } catch (const std::length_error&) {
        throw InputError("glTF " + quoteValue(file) + ": too large to load (a count beyond what memory can hold)");
    }
    try {
        validateScene(scene);
    } catch (const InputError& e) {
        throw InputError("glTF " + quoteValue(file) + ": " + e.what());
    }
    return scene;
}

Scene loadGltf(const std::string& path, const LoadOptions& options) {
    const std::string file = fileName(path);
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    const std::vector<unsigned char> bytes = gltf::readFile(path, file);
    const std::string folder = std::filesystem::path(path).parent_path().string();
    return loadGltfFromMemory(bytes, file, folder.empty() ? "." : folder, ext == ".glb", options);
}

}  // namespace viz::scene
