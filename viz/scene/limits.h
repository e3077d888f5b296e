// The sizes and magnitudes a scene may have: checked by the glTF loader before anything is allocated,
// and by validateScene for every scene however it was made. Each is a one-line error (README "Scene
// files").
#pragma once

#include <cstdint>

namespace viz::scene {

struct LoadLimits {
    static constexpr std::uint64_t kMaxFileBytes = 1ull << 30;         // the .gltf/.glb and each buffer/image file
    static constexpr int kMaxJsonDepth = 64;                           // nesting of JSON objects and arrays
    static constexpr std::uint64_t kMaxImagePixels = 16384ull * 16384;  // per image, and each side <= 16384
    static constexpr std::uint64_t kMaxTriangles = 10'000'000;          // after instancing, all meshes together
    static constexpr std::uint64_t kMaxVertices = 30'000'000;           // after instancing
    static constexpr std::uint64_t kMaxMeshInstances = 20'000;          // primitives placed by nodes
    static constexpr double kMaxCoordinate = 1e15;   // |x| of any world-space position (GPU floats square it)
    static constexpr double kMaxRadiance = 1e20;     // intensity x colour, emissive x strength
    static constexpr double kMaxSigma = 1e12;        // medium coefficients, per scene unit
};

}  // namespace viz::scene
