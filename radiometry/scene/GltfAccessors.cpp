#include "radiometry/scene/GltfAccessors.h"

#include <cmath>
#include <cstdio>
#include <cstring>

namespace radiant::detail {
namespace {

SourceLocation at(const SourceLocation& where, const std::string& what) {
    return {where.file, where.element.empty() ? what : where.element + ", " + what};
}

/// A byte count from file values, which may not fit in 64 bits.
std::string bytesText(double bytes) {
    char text[40];
    std::snprintf(text, sizeof text, "%.0f", bytes);
    return text;
}

/// The accessor's bytes: pointer to element 0 and the stride, after checking every range.
struct AccessorBytes {
    const unsigned char* first = nullptr;
    std::size_t stride = 0;
    std::size_t count = 0;
};

AccessorBytes locate(const tinygltf::Model& model, int index, int expectedType, std::size_t elementSize,
                     const SourceLocation& where, const char* role) {
    const std::string name = std::string(role) + " accessor " + std::to_string(index);
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size())
        throw RadiantError(where, std::string(role) + " accessor " + std::to_string(index) + " out of range (accessor count " +
                                      std::to_string(model.accessors.size()) + ")");
    const tinygltf::Accessor& accessor = model.accessors[static_cast<std::size_t>(index)];
    if (accessor.sparse.isSparse) throw RadiantError(at(where, name), "sparse accessors are not supported");
    if (accessor.type != expectedType)
        throw RadiantError(at(where, name), "has type " + std::to_string(accessor.type) + ", expected " + std::to_string(expectedType));
    if (accessor.bufferView < 0 || static_cast<std::size_t>(accessor.bufferView) >= model.bufferViews.size())
        throw RadiantError(at(where, name), "buffer view " + std::to_string(accessor.bufferView) + " out of range (buffer view count " +
                                                std::to_string(model.bufferViews.size()) + ")");
    const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(accessor.bufferView)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= model.buffers.size())
        throw RadiantError(at(where, name), "buffer " + std::to_string(view.buffer) + " out of range (buffer count " +
                                                std::to_string(model.buffers.size()) + ")");
    const tinygltf::Buffer& buffer = model.buffers[static_cast<std::size_t>(view.buffer)];
    // Written so that no sum can wrap around: offsets and lengths come straight from the file.
    if (view.byteOffset > buffer.data.size() || view.byteLength > buffer.data.size() - view.byteOffset)
        throw RadiantError(at(where, name), "buffer view " + std::to_string(accessor.bufferView) + " needs bytes up to " +
                                                bytesText(static_cast<double>(view.byteOffset) + static_cast<double>(view.byteLength)) + " but buffer " +
                                                std::to_string(view.buffer) + " has " + std::to_string(buffer.data.size()));
    const std::size_t stride = view.byteStride != 0 ? view.byteStride : elementSize;
    if (stride < elementSize) throw RadiantError(at(where, name), "byte stride " + std::to_string(stride) + " is smaller than an element");
    if (accessor.count > 0) {
        const std::size_t room = view.byteLength >= elementSize ? view.byteLength - elementSize : 0;
        const bool fits = view.byteLength >= elementSize && accessor.byteOffset <= room &&
                          accessor.count - 1 <= (room - accessor.byteOffset) / stride;
        const double end = static_cast<double>(accessor.byteOffset) +
                           static_cast<double>(stride) * static_cast<double>(accessor.count - 1) + static_cast<double>(elementSize);
        if (!fits)
            throw RadiantError(at(where, name), std::to_string(accessor.count) + " elements need " + bytesText(end) +
                                                    " bytes but buffer view " + std::to_string(accessor.bufferView) + " has " +
                                                    std::to_string(view.byteLength));
    }
    return {buffer.data.data() + view.byteOffset + accessor.byteOffset, stride, accessor.count};
}

template <class T>
T load(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof(T));
    return value;
}

} // namespace

std::size_t accessorCount(const tinygltf::Model& model, int index) {
    if (index < 0 || static_cast<std::size_t>(index) >= model.accessors.size()) return 0;
    return model.accessors[static_cast<std::size_t>(index)].count;
}

std::vector<glm::dvec3> readPositions(const tinygltf::Model& model, int index, const SourceLocation& where) {
    if (index >= 0 && static_cast<std::size_t>(index) < model.accessors.size() &&
        model.accessors[static_cast<std::size_t>(index)].componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
        throw RadiantError(at(where, "POSITION accessor " + std::to_string(index)), "positions must be float");
    const AccessorBytes bytes = locate(model, index, TINYGLTF_TYPE_VEC3, 3 * sizeof(float), where, "POSITION");
    std::vector<glm::dvec3> positions(bytes.count);
    for (std::size_t i = 0; i < bytes.count; ++i) {
        const unsigned char* p = bytes.first + i * bytes.stride;
        const glm::dvec3 v(load<float>(p), load<float>(p + 4), load<float>(p + 8));
        if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
            throw RadiantError(where, "vertex " + std::to_string(i) + " has a position that is not finite (" + std::to_string(v.x) +
                                          ", " + std::to_string(v.y) + ", " + std::to_string(v.z) + ")");
        positions[i] = v;
    }
    return positions;
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int index, const SourceLocation& where) {
    int componentType = 0;
    if (index >= 0 && static_cast<std::size_t>(index) < model.accessors.size())
        componentType = model.accessors[static_cast<std::size_t>(index)].componentType;
    std::size_t size = 0;
    switch (componentType) {
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: size = 1; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: size = 2; break;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: size = 4; break;
    default:
        if (index >= 0 && static_cast<std::size_t>(index) < model.accessors.size())
            throw RadiantError(at(where, "index accessor " + std::to_string(index)),
                               "component type " + std::to_string(componentType) + " is not an unsigned byte, short or int");
    }
    const AccessorBytes bytes = locate(model, index, TINYGLTF_TYPE_SCALAR, size, where, "index");
    std::vector<std::uint32_t> indices(bytes.count);
    for (std::size_t i = 0; i < bytes.count; ++i) {
        const unsigned char* p = bytes.first + i * bytes.stride;
        indices[i] = size == 1 ? p[0] : size == 2 ? load<std::uint16_t>(p) : load<std::uint32_t>(p);
    }
    return indices;
}

} // namespace radiant::detail
