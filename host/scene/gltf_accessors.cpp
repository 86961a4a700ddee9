#include "scene/gltf_accessors.h"

#include <cmath>
#include <cstring>

#include "util/error.h"

namespace rc {
namespace {

int component_bytes(int type) {
    switch (type) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

int type_components(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR:
            return 1;
        case TINYGLTF_TYPE_VEC2:
            return 2;
        case TINYGLTF_TYPE_VEC3:
            return 3;
        case TINYGLTF_TYPE_VEC4:
            return 4;
        default:
            return 0;
    }
}

// The accessor's elements as raw bytes: its first byte, the stride between elements, and the
// element size, after checking that count elements lie within its buffer view and buffer.
struct AccessorBytes {
    const unsigned char* first = nullptr;
    size_t stride = 0;
    size_t count = 0;
    int component_type = 0;
    int components = 0;
    bool normalized = false;
};

AccessorBytes accessor_bytes(const tinygltf::Model& model, int index, const std::string& what) {
    const std::string name = what + " (accessor " + std::to_string(index) + ")";
    if (index < 0 || static_cast<size_t>(index) >= model.accessors.size()) {
        throw Error(what + ": accessor " + std::to_string(index) + " does not exist");
    }
    const tinygltf::Accessor& accessor = model.accessors[index];
    if (accessor.sparse.isSparse) {
        throw Error(name + ": sparse accessors are not supported", kExitUnsupported);
    }
    AccessorBytes bytes;
    bytes.component_type = accessor.componentType;
    bytes.components = type_components(accessor.type);
    bytes.normalized = accessor.normalized;
    bytes.count = accessor.count;
    const int size = component_bytes(accessor.componentType);
    if (size == 0 || bytes.components == 0) {
        throw Error(name + ": unsupported component or element type");
    }
    if (accessor.count == 0) {
        return bytes;
    }
    if (accessor.bufferView < 0 ||
        static_cast<size_t>(accessor.bufferView) >= model.bufferViews.size()) {
        throw Error(name + ": buffer view " + std::to_string(accessor.bufferView) +
                    " does not exist");
    }
    const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
    if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model.buffers.size()) {
        throw Error(name + ": buffer " + std::to_string(view.buffer) + " does not exist");
    }
    const std::vector<unsigned char>& data = model.buffers[view.buffer].data;
    const size_t element = static_cast<size_t>(size) * bytes.components;
    bytes.stride = view.byteStride == 0 ? element : view.byteStride;
    if (bytes.stride < element || bytes.stride % size != 0) {
        throw Error(name + ": byte stride " + std::to_string(view.byteStride) + " is invalid");
    }
    // The last element's end, in the view and in the buffer, without overflow.
    const size_t limit = size_t{1} << 40;
    if (accessor.count > limit / bytes.stride || accessor.byteOffset > limit ||
        view.byteOffset > limit || view.byteLength > limit) {
        throw Error(name + ": byte range too large");
    }
    const size_t end = accessor.byteOffset + (accessor.count - 1) * bytes.stride + element;
    if (view.byteOffset + view.byteLength > data.size()) {
        throw Error(name + ": buffer view " + std::to_string(accessor.bufferView) + " (bytes " +
                    std::to_string(view.byteOffset) + " to " +
                    std::to_string(view.byteOffset + view.byteLength) +
                    ") runs past the end of buffer " + std::to_string(view.buffer) + " (" +
                    std::to_string(data.size()) + " bytes)");
    }
    if (end > view.byteLength) {
        throw Error(name + ": its " + std::to_string(accessor.count) + " elements (to byte " +
                    std::to_string(end) + ") run past the end of buffer view " +
                    std::to_string(accessor.bufferView) + " (" + std::to_string(view.byteLength) +
                    " bytes)");
    }
    bytes.first = data.data() + view.byteOffset + accessor.byteOffset;
    return bytes;
}

template <class T>
T load(const unsigned char* p) {
    T value;
    std::memcpy(&value, p, sizeof value);
    return value;
}

// Component c of element i as a float (glTF 2.0 §3.11: normalized integers map to [0, 1] or
// [-1, 1]).
float component(const AccessorBytes& b, size_t i, int c) {
    const unsigned char* p = b.first + i * b.stride + c * component_bytes(b.component_type);
    switch (b.component_type) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return load<float>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return b.normalized ? load<uint8_t>(p) / 255.0f : load<uint8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_BYTE:
            return b.normalized ? std::max(load<int8_t>(p) / 127.0f, -1.0f) : load<int8_t>(p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return b.normalized ? load<uint16_t>(p) / 65535.0f : load<uint16_t>(p);
        case TINYGLTF_COMPONENT_TYPE_SHORT:
            return b.normalized ? std::max(load<int16_t>(p) / 32767.0f, -1.0f) : load<int16_t>(p);
        default:
            return static_cast<float>(load<uint32_t>(p));
    }
}

}  // namespace

std::vector<float> read_float_accessor(const tinygltf::Model& model, int index, int components,
                                       const std::string& what) {
    const AccessorBytes b = accessor_bytes(model, index, what);
    if (b.components != components) {
        throw Error(what + " (accessor " + std::to_string(index) + "): expected " +
                    std::to_string(components) + " components, got " +
                    std::to_string(b.components));
    }
    std::vector<float> values(b.count * components);
    for (size_t i = 0; i < b.count; ++i) {
        for (int c = 0; c < components; ++c) {
            const float v = component(b, i, c);
            if (!std::isfinite(v)) {
                throw Error(what + " (accessor " + std::to_string(index) + "): element " +
                            std::to_string(i) + " is not finite");
            }
            values[i * components + c] = v;
        }
    }
    return values;
}

std::vector<unsigned> read_index_accessor(const tinygltf::Model& model, int index,
                                          const std::string& what) {
    const AccessorBytes b = accessor_bytes(model, index, what);
    if (b.components != 1 || b.normalized ||
        (b.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         b.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
         b.component_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)) {
        throw Error(what + " (accessor " + std::to_string(index) +
                    "): indices must be unsigned byte, short or int scalars");
    }
    std::vector<unsigned> values(b.count);
    for (size_t i = 0; i < b.count; ++i) {
        const unsigned char* p = b.first + i * b.stride;
        values[i] = b.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ? load<uint8_t>(p)
                    : b.component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT
                        ? load<uint16_t>(p)
                        : load<uint32_t>(p);
    }
    return values;
}

}  // namespace rc
