#include "scene/scene_source.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <type_traits>

#include "core/error.h"
#include "scene/builtin_scenes.h"
#include "scene/gltf_loader.h"
#include "scene/stiff_scenes.h"
#include "scene/validate.h"

namespace viz::scene {
namespace {

bool endsWithIgnoringCase(const std::string& s, const std::string& suffix) {
    if (s.size() < suffix.size()) return false;
    return std::equal(suffix.rbegin(), suffix.rend(), s.rbegin(),
                      [](char a, char b) { return std::tolower((unsigned char)a) == std::tolower((unsigned char)b); });
}

// FNV-1a over the bytes of each value, little-endian as laid out in memory (x86-64, aarch64).
class Hasher {
public:
    void bytes(const void* data, std::size_t n) { mHash = fnv1a64(data, n, mHash); }
    // Integers by their bytes; floating-point values with -0 folded into +0 (x + 0 does that), so
    // the hash follows values, not how a zero was computed.
    template <typename T>
    void value(const T& v) {
        if constexpr (std::is_floating_point_v<T>) {
            const T folded = v + T(0);
            bytes(&folded, sizeof(T));
        } else if constexpr (std::is_integral_v<T>) {
            bytes(&v, sizeof(T));
        } else {
            // glm vectors
            for (int i = 0; i < T::length(); ++i) value(v[i]);
        }
    }
    template <typename T>
    void array(const std::vector<T>& v) {
        value(std::uint64_t(v.size()));
        if constexpr (std::is_integral_v<T>) {
            if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
        } else {
            for (const T& x : v) value(x);
        }
    }
    std::uint64_t result() const { return mHash; }

private:
    std::uint64_t mHash = kFnvOffsetBasis;
};

}  // namespace

std::uint64_t fnv1a64(const void* data, std::size_t size, std::uint64_t hash) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) {
        hash ^= p[i];
        hash *= 0x100000001b3ULL;  // FNV 64-bit prime
    }
    return hash;
}

Scene loadScene(const std::string& nameOrPath, const LoadOptions& options) {
    Scene scene;
    if (isBuiltinScene(nameOrPath)) {
        scene = makeBuiltinScene(nameOrPath);
    } else if (nameOrPath.rfind("stiff/", 0) == 0) {
        const StiffCase* c = findStiffCase(nameOrPath.substr(6));
        if (!c) {
            std::string known;
            for (const StiffCase& k : stiffCases()) known += (known.empty() ? "" : ", ") + k.id;
            throw InputError("unknown stiff case '" + nameOrPath + "' (known: " + known + ")");
        }
        scene = buildStiffScene(*c);
    } else if (endsWithIgnoringCase(nameOrPath, ".gltf") || endsWithIgnoringCase(nameOrPath, ".glb")) {
        scene = loadGltf(nameOrPath, options);
    } else {
        std::string known;
        for (const std::string& n : builtinSceneNames()) known += (known.empty() ? "" : ", ") + n;
        throw InputError("unknown scene '" + nameOrPath + "': not a built-in scene (" + known +
                         "), not a stiff case (stiff/ID) and not a .gltf/.glb file");
    }
    validateScene(scene);
    return scene;
}

namespace {

// Meshes, materials and textures: what a GPU upload of the scene depends on.
void hashGeometry(Hasher& h, const Scene& scene) {
    h.value(std::uint64_t(scene.meshes.size()));
    for (const Mesh& m : scene.meshes) {
        h.array(m.positions);
        h.array(m.normals);
        h.array(m.uvs);
        h.array(m.indices);
        h.value(m.material);
    }
    h.value(std::uint64_t(scene.materials.size()));
    for (const Material& m : scene.materials) {
        h.value(m.baseColorFactor);
        h.value(m.baseColorTexture);
        h.value(m.emissiveFactor);
        h.value(m.emissiveStrength);
        h.value(m.emissiveTexture);
    }
    h.value(std::uint64_t(scene.textures.size()));
    for (const Texture& t : scene.textures) {
        h.value(t.width);
        h.value(t.height);
        h.array(t.rgba8);
    }
}

}  // namespace

std::uint64_t geometryContentHash(const Scene& scene) {
    Hasher h;
    hashGeometry(h, scene);
    return h.result();
}

void stampGeometry(Scene& scene) {
    const std::uint64_t hash = geometryContentHash(scene);
    scene.geometryKey = hash != 0 ? hash : 1;
}

std::uint64_t geometryKeyOf(const Scene& scene) {
    return scene.geometryKey != 0 ? scene.geometryKey : geometryContentHash(scene);
}

std::string sceneContentHash(const Scene& scene) {
    Hasher h;
    h.value(geometryKeyOf(scene));  // a stamped scene's geometry is not hashed again
    h.value(std::uint64_t(scene.lights.size()));
    for (const Light& l : scene.lights) {
        h.value(int(l.type));
        h.value(l.position);
        h.value(l.direction);
        h.value(l.colour);
        h.value(l.intensity);
        h.value(l.innerConeAngle);
        h.value(l.outerConeAngle);
        h.value(l.cookie);
        h.value(l.halfU);
        h.value(l.halfV);
        h.value(l.radiance);
        h.value(l.emissionTexture);
        h.value(l.mesh);
    }
    const Camera& c = scene.camera;
    h.value(c.position);
    h.value(c.forward);
    h.value(c.up);
    h.value(c.yfov);
    h.value(c.znear);
    h.value(c.zfar);
    h.value(c.aspectRatio);
    h.value(scene.medium.sigma_s);
    h.value(scene.medium.sigma_a);
    h.value(scene.medium.g);
    char text[17];
    std::snprintf(text, sizeof(text), "%016llx", static_cast<unsigned long long>(h.result()));
    return text;
}

}  // namespace viz::scene
