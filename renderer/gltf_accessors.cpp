// glTF validation: accessors. Component types and sizes, and the bounds-checked accessor reader
// the conversion uses (ValidatedGltf::checkAccessor/readAccessor, gltf_validate.hpp).
#include "renderer/gltf_validate.hpp"

#include "common/error.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace signstim::render {

namespace gltf_detail {

int componentCount(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return 1;
        case TINYGLTF_TYPE_VEC2: return 2;
        case TINYGLTF_TYPE_VEC3: return 3;
        case TINYGLTF_TYPE_VEC4: return 4;
        case TINYGLTF_TYPE_MAT2: return 4;
        case TINYGLTF_TYPE_MAT3: return 9;
        case TINYGLTF_TYPE_MAT4: return 16;
        default: return 0;
    }
}

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        case TINYGLTF_TYPE_VEC4: return "VEC4";
        case TINYGLTF_TYPE_MAT2: return "MAT2";
        case TINYGLTF_TYPE_MAT3: return "MAT3";
        case TINYGLTF_TYPE_MAT4: return "MAT4";
        default: return "?";
    }
}

}  // namespace gltf_detail

namespace {
using gltf_detail::at;
using gltf_detail::componentCount;
using gltf_detail::typeName;

// Accessors without a bufferView (all zeros, maybe sparse) allocate `count` elements; a
// count beyond this is treated as a broken file rather than an allocation request.
constexpr std::uint64_t kMaxUnbackedCount = 1ull << 26;

int componentSize(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

double readComponent(const std::uint8_t* p, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            std::int8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? std::max(v / 127.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
            std::uint8_t v;
            std::memcpy(&v, p, 1);
            return normalized ? v / 255.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            std::int16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? std::max(v / 32767.0, -1.0) : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            std::uint16_t v;
            std::memcpy(&v, p, 2);
            return normalized ? v / 65535.0 : v;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            std::uint32_t v;
            std::memcpy(&v, p, 4);
            return v;
        }
        default: {
            float v;
            std::memcpy(&v, p, 4);
            return v;
        }
    }
}

}  // namespace

// ---- the validated model: binary data, read through checked accessors ---------------------
ValidatedGltf::ValidatedGltf(std::unique_ptr<tinygltf::Model> model, std::string fileName)
    : model_(std::move(model)), fileName_(std::move(fileName)) {}
ValidatedGltf::ValidatedGltf(ValidatedGltf&&) noexcept = default;
ValidatedGltf& ValidatedGltf::operator=(ValidatedGltf&&) noexcept = default;
ValidatedGltf::~ValidatedGltf() = default;

void ValidatedGltf::fail(const std::string& field, const std::string& message, int line) const {
    throw InputError(fileName_, line, field, message);
}

const std::uint8_t* ValidatedGltf::viewData(int viewIndex) const {
    const tinygltf::BufferView& view = model_->bufferViews[static_cast<std::size_t>(viewIndex)];
    return model_->buffers[static_cast<std::size_t>(view.buffer)].data.data() + view.byteOffset;
}

ValidatedGltf::ByteRange ValidatedGltf::checkAccessor(int index) const {
    const tinygltf::Accessor& a = model_->accessors[static_cast<std::size_t>(index)];
    const std::string f = at("accessors", static_cast<std::size_t>(index));
    const int components = componentCount(a.type);
    const int size = componentSize(a.componentType);
    if (components == 0) fail(f + "/type", "unknown accessor type");
    if (size == 0) fail(f + "/componentType", "unknown component type " + std::to_string(a.componentType));
    if (a.normalized && (a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                         a.componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
        fail(f + "/normalized", "only byte and short components may be normalized");
    if (size < 4 && a.type >= TINYGLTF_TYPE_MAT2 && a.type <= TINYGLTF_TYPE_MAT4)
        fail(f + "/componentType", "matrices of 8/16-bit components are not supported");
    const std::uint64_t elementSize = static_cast<std::uint64_t>(components) * size;
    const std::uint64_t count = a.count;
    ByteRange range;
    if (a.bufferView >= 0) {
        const tinygltf::BufferView& view = model_->bufferViews[static_cast<std::size_t>(a.bufferView)];
        const std::uint64_t stride = view.byteStride ? view.byteStride : elementSize;
        if (stride < elementSize)
            fail(f + "/bufferView", "/bufferViews/" + std::to_string(a.bufferView) + "/byteStride " +
                                        std::to_string(stride) + " is smaller than one " +
                                        typeName(a.type) + " element (" + std::to_string(elementSize) + " bytes)");
        if (a.byteOffset % static_cast<std::size_t>(size) != 0)
            fail(f + "/byteOffset", "must be a multiple of the component size");
        // Last byte read: byteOffset + stride * (count - 1) + elementSize, overflow-safe.
        const std::uint64_t viewLength = view.byteLength;
        const bool fits = a.byteOffset <= viewLength && count - 1 <= (viewLength - a.byteOffset) / stride &&
                          a.byteOffset + stride * (count - 1) + elementSize <= viewLength;
        if (!fits)
            fail(f + "/count", "count " + std::to_string(count) + " of " + typeName(a.type) +
                                   " at byteOffset " + std::to_string(a.byteOffset) +
                                   " reads past the end of /bufferViews/" + std::to_string(a.bufferView) +
                                   " (" + std::to_string(viewLength) + " bytes)");
        range.data = viewData(a.bufferView) + a.byteOffset;
        range.stride = static_cast<std::size_t>(stride);
    } else if (count > kMaxUnbackedCount) {
        fail(f + "/count", "count " + std::to_string(count) + " without a bufferView is implausibly large");
    }
    if (a.sparse.isSparse) {
        const std::string sf = f + "/sparse";
        const std::uint64_t sparseCount = static_cast<std::uint64_t>(a.sparse.count);
        if (a.sparse.count < 1 || sparseCount > count)
            fail(sf + "/count", "must be in [1, accessor count " + std::to_string(count) + "]");
        const int indexSize = componentSize(a.sparse.indices.componentType);
        if (a.sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
            a.sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_SHORT ||
            a.sparse.indices.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT || indexSize == 0)
            fail(sf + "/indices/componentType", "must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
        auto checkPart = [&](const char* part, int view, int offset, std::uint64_t bytesEach) {
            const std::uint64_t length = model_->bufferViews[static_cast<std::size_t>(view)].byteLength;
            if (offset < 0 || static_cast<std::uint64_t>(offset) > length ||
                sparseCount > (length - static_cast<std::uint64_t>(offset)) / bytesEach)
                fail(sf + "/" + part, std::to_string(sparseCount) + " entries at byteOffset " +
                                          std::to_string(offset) + " read past the end of /bufferViews/" +
                                          std::to_string(view) + " (" + std::to_string(length) + " bytes)");
        };
        checkPart("indices", a.sparse.indices.bufferView, a.sparse.indices.byteOffset,
                  static_cast<std::uint64_t>(indexSize));
        checkPart("values", a.sparse.values.bufferView, a.sparse.values.byteOffset, elementSize);
    }
    return range;
}

std::vector<double> ValidatedGltf::readAccessor(int index, std::initializer_list<int> types,
                                                std::initializer_list<int> componentTypes,
                                                const std::string& usedAs) const {
    const tinygltf::Accessor& a = model_->accessors[static_cast<std::size_t>(index)];
    const std::string f = at("accessors", static_cast<std::size_t>(index));
    if (std::find(types.begin(), types.end(), a.type) == types.end()) {
        std::string allowed;
        for (int t : types) allowed += std::string(allowed.empty() ? "" : " or ") + typeName(t);
        fail(f + "/type", std::string(typeName(a.type)) + " cannot be used as " + usedAs + " (needs " + allowed + ")");
    }
    if (componentTypes.size() &&
        std::find(componentTypes.begin(), componentTypes.end(), a.componentType) == componentTypes.end())
        fail(f + "/componentType", "component type " + std::to_string(a.componentType) +
                                       " cannot be used as " + usedAs);
    const ByteRange range = checkAccessor(index);
    const int components = componentCount(a.type);
    const int size = componentSize(a.componentType);
    std::vector<double> values(a.count * static_cast<std::size_t>(components), 0.0);
    auto readElement = [&](const std::uint8_t* p, std::size_t element) {
        for (int c = 0; c < components; ++c)
            values[element * components + c] = readComponent(p + c * size, a.componentType, a.normalized);
    };
    if (range.data)
        for (std::size_t e = 0; e < a.count; ++e) readElement(range.data + e * range.stride, e);
    if (a.sparse.isSparse) {
        const std::uint8_t* indices = viewData(a.sparse.indices.bufferView) + a.sparse.indices.byteOffset;
        const std::uint8_t* sparseValues = viewData(a.sparse.values.bufferView) + a.sparse.values.byteOffset;
        const int indexSize = componentSize(a.sparse.indices.componentType);
        std::uint64_t previous = 0;
        for (int s = 0; s < a.sparse.count; ++s) {
            const auto target = static_cast<std::uint64_t>(
                readComponent(indices + static_cast<std::size_t>(s) * indexSize, a.sparse.indices.componentType, false));
            if (target >= a.count)
                fail(f + "/sparse/indices", "index " + std::to_string(target) + " out of range (count " +
                                                std::to_string(a.count) + ")");
            // glTF 2.0 §3.6.2.3: sparse indices MUST strictly increase.
            if (s > 0 && target <= previous)
                fail(f + "/sparse/indices", "index " + std::to_string(target) + " (entry " + std::to_string(s) +
                                                ") does not increase strictly after " + std::to_string(previous));
            previous = target;
            readElement(sparseValues + static_cast<std::size_t>(s) * components * size, static_cast<std::size_t>(target));
        }
    }
    for (std::size_t i = 0; i < values.size(); ++i)
        if (!std::isfinite(values[i]))
            fail(f, "element " + std::to_string(i / components) + " of " + usedAs + " is not finite (NaN or Inf)");
    return values;
}

}  // namespace signstim::render
