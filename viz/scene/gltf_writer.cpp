#include "scene/gltf_writer.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include <stb_image_write.h>
#include <tiny_gltf.h>

#include "core/atomic_file.h"
#include "core/error.h"

namespace viz::scene {
namespace {

constexpr int kArrayBuffer = 34962;         // GL_ARRAY_BUFFER
constexpr int kElementArrayBuffer = 34963;  // GL_ELEMENT_ARRAY_BUFFER
constexpr int kLinear = 9729;               // GL_LINEAR
constexpr int kClampToEdge = 33071;         // GL_CLAMP_TO_EDGE

// RFC 4648 base64 with padding, for data URIs.
std::string base64(const std::vector<unsigned char>& data) {
    static const char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((data.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < data.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, data.size() - i);
        std::uint32_t v = std::uint32_t(data[i]) << 16;
        if (n > 1) v |= std::uint32_t(data[i + 1]) << 8;
        if (n > 2) v |= std::uint32_t(data[i + 2]);
        for (std::size_t k = 0; k < 4; ++k) out += k <= n ? kAlphabet[(v >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

class ModelBuilder {
public:
    // binary: images go into the buffer (.glb); otherwise each is its own data:image/png URI (.gltf).
    ModelBuilder(const Scene& scene, bool binary) : mScene(scene), mBinary(binary) {
        mModel.asset.version = "2.0";
        mModel.asset.generator = "airlight";
        mModel.buffers.emplace_back();
    }

    tinygltf::Model build() {
        writeTextures();
        writeMaterials();
        tinygltf::Scene gs;
        gs.name = mScene.name;
        for (std::size_t m = 0; m < mScene.meshes.size(); ++m) gs.nodes.push_back(writeMesh(m));
        for (const Light& light : mScene.lights) {
            if (light.type != LightType::Area) gs.nodes.push_back(writeLight(light));
        }
        gs.nodes.push_back(writeCamera());
        tinygltf::Value::Object medium;
        medium["sigma_s"] = tinygltf::Value(mScene.medium.sigma_s);
        medium["sigma_a"] = tinygltf::Value(mScene.medium.sigma_a);
        medium["g"] = tinygltf::Value(mScene.medium.g);
        tinygltf::Value::Object extras;
        extras["medium"] = tinygltf::Value(std::move(medium));
        gs.extras = tinygltf::Value(std::move(extras));
        mModel.scenes.push_back(std::move(gs));
        mModel.defaultScene = 0;
        if (mUsesEmissiveStrength) mModel.extensionsUsed.push_back("KHR_materials_emissive_strength");
        return std::move(mModel);
    }

private:
    // Appends bytes to the single buffer, 4-byte aligned, and returns the new bufferView's index.
    int addView(const void* data, std::size_t bytes, int target) {
        std::vector<unsigned char>& buf = mModel.buffers[0].data;
        while (buf.size() % 4 != 0) buf.push_back(0);
        tinygltf::BufferView view;
        view.buffer = 0;
        view.byteOffset = buf.size();
        view.byteLength = bytes;
        view.target = target;
        const auto* p = static_cast<const unsigned char*>(data);
        buf.insert(buf.end(), p, p + bytes);
        mModel.bufferViews.push_back(view);
        return int(mModel.bufferViews.size() - 1);
    }

    int addAccessor(int view, int componentType, int type, std::size_t count) {
        tinygltf::Accessor acc;
        acc.bufferView = view;
        acc.componentType = componentType;
        acc.type = type;
        acc.count = count;
        mModel.accessors.push_back(acc);
        return int(mModel.accessors.size() - 1);
    }

    static void appendBytes(void* context, void* data, int size) {
        auto* out = static_cast<std::vector<unsigned char>*>(context);
        const auto* p = static_cast<const unsigned char*>(data);
        out->insert(out->end(), p, p + size);
    }

    void writeTextures() {
        for (const Texture& tex : mScene.textures) {
            std::vector<unsigned char> png;
            if (!stbi_write_png_to_func(&ModelBuilder::appendBytes, &png, tex.width, tex.height, 4,
                                        tex.rgba8.data(), tex.width * 4)) {
                throw InputError("export: could not encode texture '" + tex.name + "' as PNG");
            }
            tinygltf::Image image;
            image.name = tex.name;
            image.mimeType = "image/png";
            if (mBinary) {
                image.bufferView = addView(png.data(), png.size(), 0);
            } else {
                image.uri = "data:image/png;base64," + base64(png);
            }
            mModel.images.push_back(std::move(image));
            tinygltf::Texture gt;
            gt.name = tex.name;
            gt.source = int(mModel.images.size() - 1);
            gt.sampler = 0;
            mModel.textures.push_back(std::move(gt));
        }
        if (!mScene.textures.empty()) {
            // Our techniques filter bilinearly and clamp to edge (texture_sampling.h).
            tinygltf::Sampler sampler;
            sampler.magFilter = kLinear;
            sampler.minFilter = kLinear;
            sampler.wrapS = kClampToEdge;
            sampler.wrapT = kClampToEdge;
            mModel.samplers.push_back(sampler);
        }
    }

    void writeMaterials() {
        for (const Material& mat : mScene.materials) {
            tinygltf::Material gm;
            gm.name = mat.name;
            gm.pbrMetallicRoughness.baseColorFactor = {mat.baseColorFactor.r, mat.baseColorFactor.g,
                                                       mat.baseColorFactor.b, mat.baseColorFactor.a};
            gm.pbrMetallicRoughness.baseColorTexture.index = mat.baseColorTexture;
            // Airlight shades surfaces as Lambertian: a rough dielectric is the closest glTF material.
            gm.pbrMetallicRoughness.metallicFactor = 0.0;
            gm.pbrMetallicRoughness.roughnessFactor = 1.0;
            gm.emissiveFactor = {mat.emissiveFactor.r, mat.emissiveFactor.g, mat.emissiveFactor.b};
            gm.emissiveTexture.index = mat.emissiveTexture;
            if (mat.emissiveStrength != 1.0f) {
                tinygltf::Value::Object strength;
                strength["emissiveStrength"] = tinygltf::Value(double(mat.emissiveStrength));
                gm.extensions["KHR_materials_emissive_strength"] = tinygltf::Value(std::move(strength));
                mUsesEmissiveStrength = true;
            }
            mModel.materials.push_back(std::move(gm));
        }
    }

    int writeMesh(std::size_t m) {
        const Mesh& mesh = mScene.meshes[m];
        tinygltf::Primitive prim;
        prim.mode = TINYGLTF_MODE_TRIANGLES;
        prim.material = mesh.material;

        const int posView = addView(mesh.positions.data(), mesh.positions.size() * sizeof(glm::vec3), kArrayBuffer);
        const int pos = addAccessor(posView, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, mesh.positions.size());
        // glTF requires min and max on POSITION.
        glm::vec3 lo(0.0f), hi(0.0f);
        if (!mesh.positions.empty()) lo = hi = mesh.positions[0];
        for (const glm::vec3& p : mesh.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        mModel.accessors[std::size_t(pos)].minValues = {lo.x, lo.y, lo.z};
        mModel.accessors[std::size_t(pos)].maxValues = {hi.x, hi.y, hi.z};
        prim.attributes["POSITION"] = pos;
        if (!mesh.normals.empty()) {
            const int view = addView(mesh.normals.data(), mesh.normals.size() * sizeof(glm::vec3), kArrayBuffer);
            prim.attributes["NORMAL"] = addAccessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, mesh.normals.size());
        }
        if (!mesh.uvs.empty()) {
            const int view = addView(mesh.uvs.data(), mesh.uvs.size() * sizeof(glm::vec2), kArrayBuffer);
            prim.attributes["TEXCOORD_0"] = addAccessor(view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, mesh.uvs.size());
        }
        const int indexView = addView(mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t), kElementArrayBuffer);
        prim.indices = addAccessor(indexView, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, mesh.indices.size());

        tinygltf::Mesh gm;
        gm.name = mesh.name;
        gm.primitives.push_back(std::move(prim));
        mModel.meshes.push_back(std::move(gm));
        tinygltf::Node node;
        node.name = mesh.name;
        node.mesh = int(mModel.meshes.size() - 1);
        mModel.nodes.push_back(std::move(node));
        return int(mModel.nodes.size() - 1);
    }

    // Column-major node matrix with columns x, y, z (the node's axes in world space) and the origin.
    static std::vector<double> frameMatrix(const glm::dvec3& x, const glm::dvec3& y, const glm::dvec3& z,
                                           const glm::dvec3& origin) {
        return {x.x, x.y, x.z, 0.0, y.x, y.y, y.z, 0.0, z.x, z.y, z.z, 0.0, origin.x, origin.y, origin.z, 1.0};
    }

    int writeLight(const Light& light) {
        tinygltf::Light gl;
        gl.name = light.name;
        gl.color = {light.colour.x, light.colour.y, light.colour.z};
        gl.intensity = light.intensity;
        switch (light.type) {
            case LightType::Point: gl.type = "point"; break;
            case LightType::Spot:
                gl.type = "spot";
                gl.spot.innerConeAngle = light.innerConeAngle;
                gl.spot.outerConeAngle = light.outerConeAngle;
                break;
            default: gl.type = "directional"; break;
        }
        if (light.cookie >= 0) {
            tinygltf::Value::Object extras;
            extras["cookie"] = tinygltf::Value(light.cookie);
            gl.extras = tinygltf::Value(std::move(extras));
        }
        mModel.lights.push_back(std::move(gl));

        // The light travels along the node's -Z: z = -direction exactly; x, y complete a rotation.
        const glm::dvec3 z = -light.direction;
        const glm::dvec3 helper = std::abs(z.y) > 0.99 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
        const glm::dvec3 x = glm::normalize(glm::cross(helper, z));
        const glm::dvec3 y = glm::cross(z, x);
        tinygltf::Node node;
        node.name = light.name;
        node.matrix = frameMatrix(x, y, z, light.position);
        tinygltf::Value::Object ext;
        ext["light"] = tinygltf::Value(int(mModel.lights.size() - 1));
        node.extensions["KHR_lights_punctual"] = tinygltf::Value(std::move(ext));
        mModel.nodes.push_back(std::move(node));
        return int(mModel.nodes.size() - 1);
    }

    int writeCamera() {
        const Camera& cam = mScene.camera;
        tinygltf::Camera gc;
        gc.name = cam.name;
        gc.type = "perspective";
        gc.perspective.yfov = cam.yfov;
        gc.perspective.znear = cam.znear;
        gc.perspective.zfar = cam.zfar;
        gc.perspective.aspectRatio = cam.aspectRatio;
        mModel.cameras.push_back(std::move(gc));
        tinygltf::Node node;
        node.name = cam.name.empty() ? "camera" : cam.name;
        // Camera looks down its -Z with +Y up: z = -forward, y = up, x = y cross z.
        node.matrix = frameMatrix(glm::cross(cam.up, -cam.forward), cam.up, -cam.forward, cam.position);
        node.camera = int(mModel.cameras.size() - 1);
        mModel.nodes.push_back(std::move(node));
        return int(mModel.nodes.size() - 1);
    }

    const Scene& mScene;
    bool mBinary = false;
    tinygltf::Model mModel;
    bool mUsesEmissiveStrength = false;
};

}  // namespace

void writeGltf(const Scene& scene, const std::string& path) {
    namespace fs = std::filesystem;
    const fs::path target(path);
    std::string ext = target.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (ext != ".gltf" && ext != ".glb") {
        throw InputError("export '" + path + "': the file name must end in .gltf or .glb");
    }
    const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) {
        throw InputError("export '" + path + "': folder '" + folder.string() + "' does not exist");
    }

    tinygltf::Model model = ModelBuilder(scene, ext == ".glb").build();
    std::ostringstream out(std::ios::binary);
    tinygltf::TinyGLTF gltf;
    // Images are already encoded (data URIs or buffer views): no image writer may re-encode them.
    gltf.SetImageWriter(nullptr, nullptr);
    if (!gltf.WriteGltfSceneToStream(&model, out, /*prettyPrint=*/ext == ".gltf", /*writeBinary=*/ext == ".glb")) {
        throw InputError("export '" + path + "': could not serialise the scene");
    }
    const std::string bytes = out.str();

    // Renamed over the target only once complete: a failed export leaves no partial file.
    const std::string error = writeFileAtomically(target, std::string_view(bytes.data(), bytes.size()));
    if (!error.empty()) throw InputError("export '" + path + "': " + error);
}

}  // namespace viz::scene
