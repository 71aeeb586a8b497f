#pragma once
// Reading the elements of one glTF accessor, whatever its component type, with bounds checked once.
// Internal to the glTF loader (scene/gltf_loader.cpp).
#include <array>
#include <cstring>
#include <string>

#include <tiny_gltf.h>

#include "base/log.hpp"
#include "base/result.hpp"

namespace fx::gltf_detail {

// glTF's numeric codes (the spec's values; tinygltf defines the same numbers as macros).
constexpr int kByte = 5120, kUnsignedByte = 5121, kShort = 5122, kUnsignedShort = 5123, kUnsignedInt = 5125,
              kFloat = 5126;
// The most elements one accessor may have: 16.7 million (2^24). It bounds what an accessor without a
// buffer view (all zeros) or a file's count can make fxlab allocate; docs/scene-format.md lists it.
constexpr std::size_t kMaxAccessorElements = std::size_t(1) << 24;

// What a reader of an accessor accepts, checked before the bounds so that a wrong type is named as such
// (a float JOINTS_0 is "must be unsigned 8- or 16-bit", not "reads past the end of its buffer").
struct AccessorShape {
    int components = 0;          // 0: any
    std::array<int, 3> types{};  // allowed component types; all 0: any
    const char* expected = "";   // how the allowed shape reads in a message: "float MAT4"
};

inline const char* componentTypeName(int type) {
    switch (type) {
        case kByte:
            return "signed 8-bit";
        case kUnsignedByte:
            return "unsigned 8-bit";
        case kShort:
            return "signed 16-bit";
        case kUnsignedShort:
            return "unsigned 16-bit";
        case kUnsignedInt:
            return "unsigned 32-bit";
        case kFloat:
            return "float";
    }
    return "unknown";
}

// a + b and a * b on sizes from a file, refusing instead of wrapping around.
inline bool addFits(std::size_t a, std::size_t b, std::size_t& sum) {
    return !__builtin_add_overflow(a, b, &sum);
}
inline bool multiplyFits(std::size_t a, std::size_t b, std::size_t& product) {
    return !__builtin_mul_overflow(a, b, &product);
}

// Reads the elements of one accessor, whatever its component type, with bounds checked once. Every
// number from the file (count, offsets, stride, lengths) meets the others in checked arithmetic, so no
// combination of them can wrap around and pass.
class AccessorReader {
public:
    static Result<AccessorReader> open(const tinygltf::Model& m, int index, const std::string& what,
                                       const AccessorShape& shape = {}) {
        if (index < 0 || static_cast<std::size_t>(index) >= m.accessors.size())
            return Error{cat(what, ": accessor ", index, " does not exist")};
        const tinygltf::Accessor& a = m.accessors[static_cast<std::size_t>(index)];
        AccessorReader r;
        r.componentType_ = a.componentType;
        r.normalized_ = a.normalized;
        r.components_ = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
        r.count_ = a.count;
        int componentSize = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
        if (r.components_ <= 0 || componentSize <= 0)
            return Error{cat(what, ": accessor ", index, " has an unknown type or component type")};
        bool typeAllowed = shape.types == std::array<int, 3>{};
        for (int type : shape.types) typeAllowed = typeAllowed || (type != 0 && type == a.componentType);
        if ((shape.components > 0 && r.components_ != shape.components) || !typeAllowed)
            return Error{cat(what, ": must be ", shape.expected, ", not ", componentTypeName(a.componentType),
                             " with ", r.components_, " component(s) (accessor ", index, ")")};
        r.componentSize_ = static_cast<std::size_t>(componentSize);
        if (a.sparse.isSparse)
            return Error{cat(what, ": accessor ", index, " is sparse, which fxlab does not read")};
        if (r.count_ > kMaxAccessorElements)
            return Error{cat(what, ": accessor ", index, " has ", r.count_, " elements; fxlab reads at most ",
                             kMaxAccessorElements, " per accessor")};
        if (a.bufferView < 0) return r;  // no data: every element is zero (the spec's rule)
        if (static_cast<std::size_t>(a.bufferView) >= m.bufferViews.size())
            return Error{cat(what, ": accessor ", index, " names buffer view ", a.bufferView,
                             ", which does not exist")};
        const tinygltf::BufferView& view = m.bufferViews[static_cast<std::size_t>(a.bufferView)];
        if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= m.buffers.size())
            return Error{cat(what, ": buffer view ", a.bufferView, " names a buffer that does not exist")};
        const auto& buffer = m.buffers[static_cast<std::size_t>(view.buffer)].data;
        const std::size_t element = r.componentSize_ * static_cast<std::size_t>(r.components_);
        r.stride_ = view.byteStride > 0 ? view.byteStride : element;
        if (r.stride_ < element)
            return Error{cat(what, ": buffer view ", a.bufferView, " has byteStride ", r.stride_,
                             ", less than one element of accessor ", index, " (", element, " bytes)")};
        // The view must lie inside its buffer, and the accessor's elements inside the view.
        std::size_t viewEnd = 0, start = 0, lastStart = 0, needed = 0, accessorEnd = 0;
        if (!addFits(view.byteOffset, view.byteLength, viewEnd) || viewEnd > buffer.size())
            return Error{cat(what, ": buffer view ", a.bufferView, " (offset ", view.byteOffset, ", length ",
                             view.byteLength, ") lies outside its buffer of ", buffer.size(), " bytes")};
        bool fits = r.count_ == 0 ||
                    (multiplyFits(r.stride_, r.count_ - 1, lastStart) && addFits(lastStart, element, needed));
        if (!fits || !addFits(a.byteOffset, needed, accessorEnd) || accessorEnd > view.byteLength)
            return Error{cat(what, ": accessor ", index, " (", r.count_, " elements of ", element,
                             " bytes, stride ", r.stride_, ", offset ", a.byteOffset,
                             ") reads past the end of buffer view ", a.bufferView, " (", view.byteLength,
                             " bytes)")};
        start = view.byteOffset + a.byteOffset;  // <= viewEnd <= buffer.size(): cannot wrap
        r.data_ = buffer.data() + start;
        return r;
    }

    std::size_t count() const { return count_; }
    int components() const { return components_; }
    int componentType() const { return componentType_; }

    // A component as a float: normalised integers map to [0, 1] or [-1, 1], others keep their value.
    float real(std::size_t i, int c) const {
        if (!data_ || c >= components_) return 0.0f;
        const unsigned char* p = data_ + i * stride_ + static_cast<std::size_t>(c) * componentSize_;
        switch (componentType_) {
            case kFloat:
                return load<float>(p);
            case kUnsignedByte:
                return scaled(load<std::uint8_t>(p), 255.0f);
            case kUnsignedShort:
                return scaled(load<std::uint16_t>(p), 65535.0f);
            case kUnsignedInt:
                return static_cast<float>(load<std::uint32_t>(p));
            case kByte:
                return normalized_ ? std::max(float(load<std::int8_t>(p)) / 127.0f, -1.0f)
                                   : load<std::int8_t>(p);
            case kShort:
                return normalized_ ? std::max(float(load<std::int16_t>(p)) / 32767.0f, -1.0f)
                                   : load<std::int16_t>(p);
        }
        return 0.0f;
    }
    // A component as an unsigned integer (indices, joints).
    std::uint32_t whole(std::size_t i, int c) const {
        if (!data_ || c >= components_) return 0;
        const unsigned char* p = data_ + i * stride_ + static_cast<std::size_t>(c) * componentSize_;
        switch (componentType_) {
            case kUnsignedByte:
                return load<std::uint8_t>(p);
            case kUnsignedShort:
                return load<std::uint16_t>(p);
            case kUnsignedInt:
                return load<std::uint32_t>(p);
        }
        return 0;
    }
    glm::vec4 vec(std::size_t i) const { return {real(i, 0), real(i, 1), real(i, 2), real(i, 3)}; }

private:
    template <class T>
    static T load(const unsigned char* p) {
        T value;
        std::memcpy(&value, p, sizeof(T));
        return value;
    }
    float scaled(float v, float max) const { return normalized_ ? v / max : v; }

    const unsigned char* data_ = nullptr;
    std::size_t stride_ = 0, componentSize_ = 0, count_ = 0;
    int components_ = 0, componentType_ = 0;
    bool normalized_ = false;
};

}  // namespace fx::gltf_detail
