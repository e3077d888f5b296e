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
#include "scene/validate.h"

namespace viz::scene {
namespace {

constexpr double kDefaultZfar = 1000.0;  // glTF infinite projection: zfar absent
constexpr int kMaxNodeDepth = 256;       // deeper trees are treated as cycles

// ---- accessors ----

// Where an accessor's elements live, after checking that all of them fit in their bufferView and the
// bufferView in its buffer.
struct ElementRange {
    const unsigned char* data = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
    int componentType = 0;
    int components = 0;
    bool normalized = false;
};

class Reader {
public:
    Reader(const tinygltf::Model& model, std::string file) : mModel(model), mFile(std::move(file)) {}

    [[noreturn]] void fail(const std::string& what) const { throw InputError("glTF '" + mFile + "': " + what); }

    ElementRange range(int accessorIndex, const std::string& what) const {
        if (accessorIndex < 0 || std::size_t(accessorIndex) >= mModel.accessors.size()) {
            fail(what + ": accessor " + std::to_string(accessorIndex) + " does not exist");
        }
        const tinygltf::Accessor& acc = mModel.accessors[std::size_t(accessorIndex)];
        const std::string name = "accessor " + std::to_string(accessorIndex) + " (" + what + ")";
        if (acc.sparse.isSparse) fail(name + " is sparse, which is not supported");
        if (acc.bufferView < 0 || std::size_t(acc.bufferView) >= mModel.bufferViews.size()) {
            fail(name + " has no valid bufferView");
        }
        const tinygltf::BufferView& view = mModel.bufferViews[std::size_t(acc.bufferView)];
        if (view.buffer < 0 || std::size_t(view.buffer) >= mModel.buffers.size()) {
            fail("bufferView " + std::to_string(acc.bufferView) + " refers to missing buffer " +
                 std::to_string(view.buffer));
        }
        const tinygltf::Buffer& buffer = mModel.buffers[std::size_t(view.buffer)];
        if (view.byteOffset + view.byteLength > buffer.data.size()) {
            fail("bufferView " + std::to_string(acc.bufferView) + " is out of range of buffer " +
                 std::to_string(view.buffer) + " (needs " + std::to_string(view.byteOffset + view.byteLength) +
                 " bytes, the buffer has " + std::to_string(buffer.data.size()) + ")");
        }
        const int componentSize = tinygltf::GetComponentSizeInBytes(std::uint32_t(acc.componentType));
        const int components = tinygltf::GetNumComponentsInType(std::uint32_t(acc.type));
        if (componentSize <= 0 || components <= 0) fail(name + " has an invalid type or componentType");
        const std::size_t elementSize = std::size_t(componentSize) * std::size_t(components);
        const std::size_t stride = view.byteStride > 0 ? view.byteStride : elementSize;
        if (acc.count > 0) {
            const std::size_t end = acc.byteOffset + stride * (acc.count - 1) + elementSize;
            if (end > view.byteLength) {
                fail(name + " is out of range of bufferView " + std::to_string(acc.bufferView) + " (needs " +
                     std::to_string(end) + " bytes, the view has " + std::to_string(view.byteLength) + ")");
            }
        }
        ElementRange r;
        r.data = buffer.data.data() + view.byteOffset + acc.byteOffset;
        r.stride = stride;
        r.count = acc.count;
        r.componentType = acc.componentType;
        r.components = components;
        r.normalized = acc.normalized;
        return r;
    }

    // Component c of element i as a double, with glTF's normalisation of integer types when asked.
    static double component(const ElementRange& r, std::size_t i, int c) {
        const unsigned char* p = r.data + r.stride * i;
        auto load = [&](auto tag) {
            decltype(tag) v;
            std::memcpy(&v, p + sizeof(v) * std::size_t(c), sizeof(v));
            return v;
        };
        switch (r.componentType) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: return double(load(float{}));
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
                const double v = load(std::uint8_t{});
                return r.normalized ? v / 255.0 : v;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                const double v = load(std::uint16_t{});
                return r.normalized ? v / 65535.0 : v;
            }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return double(load(std::uint32_t{}));
            case TINYGLTF_COMPONENT_TYPE_BYTE: {
                const double v = load(std::int8_t{});
                return r.normalized ? std::max(v / 127.0, -1.0) : v;
            }
            case TINYGLTF_COMPONENT_TYPE_SHORT: {
                const double v = load(std::int16_t{});
                return r.normalized ? std::max(v / 32767.0, -1.0) : v;
            }
            default: return 0.0;
        }
    }

    std::vector<glm::vec3> readVec3Float(int accessorIndex, const std::string& what) const {
        const ElementRange r = range(accessorIndex, what);
        if (r.components != 3 || r.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
            fail("accessor " + std::to_string(accessorIndex) + " (" + what + ") must be VEC3 FLOAT");
        }
        std::vector<glm::vec3> out(r.count);
        for (std::size_t i = 0; i < r.count; ++i) std::memcpy(&out[i], r.data + r.stride * i, sizeof(glm::vec3));
        return out;
    }

    std::vector<glm::vec2> readUv(int accessorIndex, const std::string& what) const {
        const ElementRange r = range(accessorIndex, what);
        if (r.components != 2) fail("accessor " + std::to_string(accessorIndex) + " (" + what + ") must be VEC2");
        std::vector<glm::vec2> out(r.count);
        for (std::size_t i = 0; i < r.count; ++i) {
            if (r.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT) {
                std::memcpy(&out[i], r.data + r.stride * i, sizeof(glm::vec2));
            } else {
                out[i] = glm::vec2(float(component(r, i, 0)), float(component(r, i, 1)));
            }
        }
        return out;
    }

    std::vector<std::uint32_t> readIndices(int accessorIndex, const std::string& what) const {
        const ElementRange r = range(accessorIndex, what);
        if (r.components != 1 || (r.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                  r.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                  r.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
            fail("accessor " + std::to_string(accessorIndex) + " (" + what + ") must be an unsigned SCALAR");
        }
        std::vector<std::uint32_t> out(r.count);
        for (std::size_t i = 0; i < r.count; ++i) out[i] = std::uint32_t(component(r, i, 0));
        return out;
    }

private:
    const tinygltf::Model& mModel;
    std::string mFile;
};

// ---- helpers ----

double numberOr(const tinygltf::Value& obj, const char* key, double fallback) {
    if (!obj.IsObject() || !obj.Has(key)) return fallback;
    const tinygltf::Value& v = obj.Get(key);
    return v.IsNumber() ? v.GetNumberAsDouble() : fallback;
}

// Node-local matrix: 'matrix' (column-major) or T * R * S.
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

// Decoded image (1-4 channels of 8 or 16 bits) to RGBA8: grey replicates into R, G, B; missing alpha
// is opaque; 16-bit values are rounded to 8 bits.
std::vector<std::uint8_t> toRgba8(const tinygltf::Image& image) {
    const std::size_t pixels = std::size_t(image.width) * std::size_t(image.height);
    const std::size_t channels = std::size_t(std::clamp(image.component, 1, 4));
    const bool wide = image.bits == 16;
    auto channel = [&](std::size_t p, std::size_t c) -> std::uint8_t {
        const std::size_t at = p * channels + c;
        if (!wide) return image.image[at];
        std::uint16_t w;
        std::memcpy(&w, &image.image[2 * at], 2);
        return std::uint8_t((unsigned(w) + 128u) / 257u);
    };
    std::vector<std::uint8_t> out(pixels * 4);
    for (std::size_t p = 0; p < pixels; ++p) {
        std::uint8_t* o = &out[p * 4];
        if (channels <= 2) {
            o[0] = o[1] = o[2] = channel(p, 0);
            o[3] = channels == 2 ? channel(p, 1) : 255;
        } else {
            for (std::size_t c = 0; c < 3; ++c) o[c] = channel(p, c);
            o[3] = channels == 4 ? channel(p, 3) : 255;
        }
    }
    return out;
}

// A camera that sees the whole bounding box, looking at its centre from above and to the side.
Camera frameScene(const Scene& scene) {
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
    for (const Mesh& mesh : scene.meshes) {
        for (const glm::vec3& p : mesh.positions) {
            lo = glm::min(lo, glm::dvec3(p));
            hi = glm::max(hi, glm::dvec3(p));
        }
    }
    if (lo.x > hi.x) lo = hi = glm::dvec3(0.0);
    const glm::dvec3 centre = 0.5 * (lo + hi);
    const double radius = std::max(0.5 * glm::length(hi - lo), 1e-3);
    Camera cam;
    cam.name = "framed";
    cam.yfov = 0.8;
    const glm::dvec3 fromCentre = glm::normalize(glm::dvec3(0.6, 0.45, 1.0));
    // Distance at which a sphere of the given radius fits in the vertical field of view.
    const double distance = 1.1 * radius / std::sin(0.5 * cam.yfov);
    cam.position = centre + distance * fromCentre;
    cam.forward = -fromCentre;
    cam.up = glm::normalize(glm::dvec3(0, 1, 0) - glm::dot(glm::dvec3(0, 1, 0), cam.forward) * cam.forward);
    cam.znear = std::max(1e-3, 0.01 * radius);
    cam.zfar = distance + 2.0 * radius;
    return cam;
}

std::string fileName(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// One line: tinygltf separates messages with newlines.
std::string firstLine(const std::string& s) {
    std::string line = s.substr(0, s.find('\n'));
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    return line;
}

// ---- the loader ----

class Loader {
public:
    Loader(const tinygltf::Model& model, const std::string& file) : mModel(model), mFile(file), mRead(model, file) {}

    Scene load() {
        checkExtensions();
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
            std::set<int> children;
            for (const auto& node : mModel.nodes) children.insert(node.children.begin(), node.children.end());
            for (int n = 0; n < int(mModel.nodes.size()); ++n) {
                if (!children.count(n)) roots.push_back(n);
            }
        }
        if (mScene.name.empty()) mScene.name = std::filesystem::path(mFile).stem().string();
        for (int root : roots) visit(root, glm::dmat4(1.0), 0);

        // Area lights after the punctual ones, in mesh order.
        for (int m = 0; m < int(mScene.meshes.size()); ++m) {
            const Mesh& mesh = mScene.meshes[std::size_t(m)];
            if (mesh.material >= 0 && mScene.materials[std::size_t(mesh.material)].isEmissive()) {
                try {
                    mScene.lights.push_back(areaLightFromMesh(mScene, m));
                } catch (const InputError& e) {
                    mRead.fail(e.what());
                }
            }
        }
        loadMedium(sceneIndex);
        if (!mHaveCamera) {
            mScene.camera = frameScene(mScene);
            mScene.notes.push_back("no camera: framed the scene");
        }
        return std::move(mScene);
    }

private:
    void checkExtensions() const {
        static const std::set<std::string> kSupported = {"KHR_lights_punctual", "KHR_materials_emissive_strength"};
        for (const std::string& ext : mModel.extensionsRequired) {
            if (!kSupported.count(ext)) mRead.fail("requires unsupported extension " + ext);
        }
    }

    void loadTextures() {
        for (std::size_t t = 0; t < mModel.textures.size(); ++t) {
            const tinygltf::Texture& gt = mModel.textures[t];
            if (gt.source < 0 || std::size_t(gt.source) >= mModel.images.size()) {
                mRead.fail("texture " + std::to_string(t) + " has no valid image source");
            }
            const tinygltf::Image& image = mModel.images[std::size_t(gt.source)];
            if (image.image.empty() || image.width <= 0 || image.height <= 0) {
                mRead.fail("image " + std::to_string(gt.source) + " could not be decoded");
            }
            Texture tex;
            tex.name = !gt.name.empty() ? gt.name : image.name;
            tex.width = image.width;
            tex.height = image.height;
            tex.rgba8 = toRgba8(image);
            mScene.textures.push_back(std::move(tex));
        }
    }

    int textureIndex(int index, const std::string& who) const {
        if (index < -1 || index >= int(mModel.textures.size())) {
            mRead.fail(who + " refers to missing texture " + std::to_string(index));
        }
        return index;
    }

    void loadMaterials() {
        for (std::size_t m = 0; m < mModel.materials.size(); ++m) {
            const tinygltf::Material& gm = mModel.materials[m];
            const std::string who = "material " + std::to_string(m);
            Material mat;
            mat.name = gm.name;
            const auto& f = gm.pbrMetallicRoughness.baseColorFactor;
            if (f.size() == 4) mat.baseColorFactor = glm::vec4(float(f[0]), float(f[1]), float(f[2]), float(f[3]));
            mat.baseColorTexture = textureIndex(gm.pbrMetallicRoughness.baseColorTexture.index, who);
            if (gm.emissiveFactor.size() == 3) {
                mat.emissiveFactor = glm::vec3(float(gm.emissiveFactor[0]), float(gm.emissiveFactor[1]),
                                               float(gm.emissiveFactor[2]));
            }
            mat.emissiveTexture = textureIndex(gm.emissiveTexture.index, who);
            const auto strength = gm.extensions.find("KHR_materials_emissive_strength");
            if (strength != gm.extensions.end()) {
                mat.emissiveStrength = float(numberOr(strength->second, "emissiveStrength", 1.0));
            }
            if (gm.pbrMetallicRoughness.baseColorTexture.texCoord != 0 || gm.emissiveTexture.texCoord != 0) {
                mScene.notes.push_back(who + ": only TEXCOORD_0 is used");
            }
            mScene.materials.push_back(std::move(mat));
        }
    }

    void visit(int nodeIndex, const glm::dmat4& parent, int depth) {
        if (nodeIndex < 0 || std::size_t(nodeIndex) >= mModel.nodes.size()) {
            mRead.fail("node " + std::to_string(nodeIndex) + " does not exist");
        }
        if (depth > kMaxNodeDepth) mRead.fail("node hierarchy is cyclic or deeper than 256");
        const tinygltf::Node& node = mModel.nodes[std::size_t(nodeIndex)];
        const glm::dmat4 world = parent * localMatrix(node);
        if (node.mesh >= 0) loadMesh(node.mesh, world);
        if (node.camera >= 0 && !mHaveCamera) loadCamera(node.camera, world);
        const auto light = node.extensions.find("KHR_lights_punctual");
        if (light != node.extensions.end()) {
            loadLight(int(numberOr(light->second, "light", -1.0)), world, node.name);
        }
        for (int child : node.children) visit(child, world, depth + 1);
    }

    void loadMesh(int meshIndex, const glm::dmat4& world) {
        if (std::size_t(meshIndex) >= mModel.meshes.size()) mRead.fail("mesh " + std::to_string(meshIndex) + " does not exist");
        const tinygltf::Mesh& gm = mModel.meshes[std::size_t(meshIndex)];
        const bool identity = world == glm::dmat4(1.0);
        const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(world)));
        // A mirroring transform turns counter-clockwise into clockwise; swap two indices to undo it.
        const bool mirrored = glm::determinant(glm::dmat3(world)) < 0.0;
        for (std::size_t p = 0; p < gm.primitives.size(); ++p) {
            const tinygltf::Primitive& prim = gm.primitives[p];
            const std::string who = "mesh " + std::to_string(meshIndex) + (gm.name.empty() ? "" : " '" + gm.name + "'") +
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

            if (!identity) {
                for (glm::vec3& q : mesh.positions) q = glm::vec3(world * glm::dvec4(glm::dvec3(q), 1.0));
                for (glm::vec3& n : mesh.normals) {
                    const glm::dvec3 t = normalMatrix * glm::dvec3(n);
                    const double len = glm::length(t);
                    n = len > 0.0 ? glm::vec3(t / len) : n;
                }
                if (mirrored) {
                    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
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
        if (lightIndex < 0 || std::size_t(lightIndex) >= mModel.lights.size()) {
            mRead.fail("KHR_lights_punctual light " + std::to_string(lightIndex) + " does not exist");
        }
        const tinygltf::Light& gl = mModel.lights[std::size_t(lightIndex)];
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
            mRead.fail("light " + std::to_string(lightIndex) + " has unknown type '" + gl.type + "'");
        }
        light.position = glm::dvec3(world[3]);
        light.direction = unitOrSelf(-glm::dvec3(world[2]));
        if (gl.color.size() == 3) light.color = glm::dvec3(gl.color[0], gl.color[1], gl.color[2]);
        light.intensity = gl.intensity;
        if (gl.extras.IsObject() && gl.extras.Has("cookie")) {
            const tinygltf::Value& cookie = gl.extras.Get("cookie");
            if (!cookie.IsInt()) mRead.fail("light " + std::to_string(lightIndex) + ": extras.cookie must be a texture index");
            if (light.type != LightType::Spot) mRead.fail("light " + std::to_string(lightIndex) + ": only spot lights can have a cookie");
            light.cookie = textureIndex(cookie.GetNumberAsInt(), "light " + std::to_string(lightIndex) + " cookie");
        }
        mScene.lights.push_back(light);
    }

    void loadMedium(int sceneIndex) {
        const tinygltf::Value* medium = nullptr;
        if (std::size_t(sceneIndex) < mModel.scenes.size()) {
            const tinygltf::Value& extras = mModel.scenes[std::size_t(sceneIndex)].extras;
            if (extras.IsObject() && extras.Has("medium")) medium = &extras.Get("medium");
        }
        if (!medium) {
            mScene.medium = Medium{0.05, 0.0, 0.0};
            mScene.notes.push_back("no medium in the scene's extras: using sigma_s = 0.05, sigma_a = 0, g = 0");
            return;
        }
        if (!medium->IsObject()) mRead.fail("scene extras.medium must be an object");
        mScene.medium.sigma_s = numberOr(*medium, "sigma_s", 0.05);
        mScene.medium.sigma_a = numberOr(*medium, "sigma_a", 0.0);
        mScene.medium.g = numberOr(*medium, "g", 0.0);
    }

    const tinygltf::Model& mModel;
    std::string mFile;
    Reader mRead;
    Scene mScene;
    bool mHaveCamera = false;
};

}  // namespace

Scene loadGltf(const std::string& path) {
    const std::string file = fileName(path);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) {
        throw InputError("glTF '" + path + "': no such file");
    }
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });

    tinygltf::TinyGLTF gltf;
    tinygltf::Model model;
    std::string err, warn;
    const bool ok = ext == ".glb" ? gltf.LoadBinaryFromFile(&model, &err, &warn, path)
                                  : gltf.LoadASCIIFromFile(&model, &err, &warn, path);
    if (!ok) {
        std::string why = firstLine(err.empty() ? warn : err);
        if (why.find("JSON") != std::string::npos || why.find("json") != std::string::npos ||
            why.find("parse") != std::string::npos) {
            why = "malformed JSON (" + why + ")";
        } else if (why.find("size mismatch") != std::string::npos || why.find("Failed to load external") != std::string::npos ||
                   why.find("File not found") != std::string::npos ||
                   why.find("decode") != std::string::npos || why.find("buffer") != std::string::npos) {
            why = "missing or short buffer/image (" + why + ")";
        }
        throw InputError("glTF '" + file + "': " + why);
    }
    Scene scene = Loader(model, file).load();
    try {
        validateScene(scene);
    } catch (const InputError& e) {
        throw InputError("glTF '" + file + "': " + e.what());
    }
    return scene;
}

}  // namespace viz::scene
