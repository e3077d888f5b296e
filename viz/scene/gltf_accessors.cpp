#include "scene/gltf_accessors.h"

#include <algorithm>
#include <cstring>

#include <tiny_gltf.h>

#include "core/error.h"

namespace viz::scene::gltf {
namespace {

// a + b and a * b, or false when the result does not fit in 64 bits.
bool add(std::uint64_t a, std::uint64_t b, std::uint64_t& out) { return !__builtin_add_overflow(a, b, &out); }
bool mul(std::uint64_t a, std::uint64_t b, std::uint64_t& out) { return !__builtin_mul_overflow(a, b, &out); }

// Component c of element i as a double, with glTF's normalisation of integer types when asked.
double component(const ElementRange& r, std::size_t i, int c) {
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

}  // namespace

void AccessorReader::fail(const std::string& what) const { throw InputError(mPrefix + what); }

ElementRange AccessorReader::range(int accessorIndex, const std::string& what) const {
    if (accessorIndex < 0 || std::size_t(accessorIndex) >= mModel.accessors.size()) {
        fail(what + ": accessor " + std::to_string(accessorIndex) + " does not exist");
    }
    const tinygltf::Accessor& acc = mModel.accessors[std::size_t(accessorIndex)];
    const std::string name = "accessor " + std::to_string(accessorIndex) + " (" + what + ")";
    if (acc.sparse.isSparse) fail(name + " is sparse, which is not supported");
    if (acc.bufferView < 0 || std::size_t(acc.bufferView) >= mModel.bufferViews.size()) {
        fail(name + " has no valid bufferView");
    }
    const std::string viewName = "bufferView " + std::to_string(acc.bufferView);
    const tinygltf::BufferView& view = mModel.bufferViews[std::size_t(acc.bufferView)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= mModel.buffers.size()) {
        fail(viewName + " refers to missing buffer " + std::to_string(view.buffer));
    }
    const tinygltf::Buffer& buffer = mModel.buffers[std::size_t(view.buffer)];
    std::uint64_t viewEnd = 0;
    if (!add(view.byteOffset, view.byteLength, viewEnd) || viewEnd > buffer.data.size()) {
        fail(viewName + " (byteOffset " + std::to_string(view.byteOffset) + ", byteLength " +
             std::to_string(view.byteLength) + ") is out of range of buffer " + std::to_string(view.buffer) + " (" +
             std::to_string(buffer.data.size()) + " bytes)");
    }
    const int componentSize = tinygltf::GetComponentSizeInBytes(std::uint32_t(acc.componentType));
    const int components = tinygltf::GetNumComponentsInType(std::uint32_t(acc.type));
    if (componentSize <= 0 || components <= 0) fail(name + " has an invalid type or componentType");
    const std::uint64_t elementSize = std::uint64_t(componentSize) * std::uint64_t(components);
    if (view.byteStride != 0 && view.byteStride < elementSize) {
        fail(viewName + ": byteStride " + std::to_string(view.byteStride) + " is smaller than " + name + "'s element (" +
             std::to_string(elementSize) + " bytes)");
    }
    const std::uint64_t stride = view.byteStride > 0 ? view.byteStride : elementSize;
    if (acc.count > 0) {
        // byteOffset + stride * (count - 1) + elementSize <= byteLength, each step checked.
        std::uint64_t span = 0, end = 0;
        if (!mul(stride, std::uint64_t(acc.count) - 1, span) || !add(span, elementSize, end) ||
            !add(end, acc.byteOffset, end) || end > view.byteLength) {
            fail(name + " (byteOffset " + std::to_string(acc.byteOffset) + ", count " + std::to_string(acc.count) +
                 ", stride " + std::to_string(stride) + ") is out of range of " + viewName + " (" +
                 std::to_string(view.byteLength) + " bytes)");
        }
    }
    ElementRange r;
    r.data = buffer.data.data() + view.byteOffset + acc.byteOffset;
    r.stride = std::size_t(stride);
    r.count = acc.count;
    r.componentType = acc.componentType;
    r.components = components;
    r.normalized = acc.normalized;
    return r;
}

std::vector<glm::vec3> AccessorReader::readVec3Float(int accessorIndex, const std::string& what) const {
    const ElementRange r = range(accessorIndex, what);
    if (r.components != 3 || r.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) {
        fail("accessor " + std::to_string(accessorIndex) + " (" + what + ") must be VEC3 FLOAT");
    }
    std::vector<glm::vec3> out(r.count);
    for (std::size_t i = 0; i < r.count; ++i) std::memcpy(&out[i], r.data + r.stride * i, sizeof(glm::vec3));
    return out;
}

std::vector<glm::vec2> AccessorReader::readUv(int accessorIndex, const std::string& what) const {
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

std::vector<std::uint32_t> AccessorReader::readIndices(int accessorIndex, const std::string& what) const {
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

}  // namespace viz::scene::gltf
