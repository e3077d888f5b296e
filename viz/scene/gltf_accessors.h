// Reading glTF accessors safely (internal to viz_scene): every offset, stride, count and length is
// checked with overflow-checked 64-bit arithmetic before a byte is read, so no file can make the loader
// read outside a buffer, whatever its numbers (offsets near 2^64, counts near 2^62, strides that wrap).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace tinygltf {
class Model;
}

namespace viz::scene::gltf {

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

class AccessorReader {
public:
    // prefix starts every message ("glTF 'FILE': ").
    AccessorReader(const tinygltf::Model& model, std::string prefix) : mModel(model), mPrefix(std::move(prefix)) {}

    [[noreturn]] void fail(const std::string& what) const;

    // The element count of an accessor, checked for range (for budgets before anything is read).
    std::size_t count(int accessorIndex, const std::string& what) const { return range(accessorIndex, what).count; }

    ElementRange range(int accessorIndex, const std::string& what) const;
    std::vector<glm::vec3> readVec3Float(int accessorIndex, const std::string& what) const;
    std::vector<glm::vec2> readUv(int accessorIndex, const std::string& what) const;
    std::vector<std::uint32_t> readIndices(int accessorIndex, const std::string& what) const;

private:
    const tinygltf::Model& mModel;
    std::string mPrefix;
};

}  // namespace viz::scene::gltf
