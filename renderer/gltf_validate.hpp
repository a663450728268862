#pragma once
// glTF 2.0 validation, the first half of loading a model (gltf_loader.hpp converts what
// passes into a Scene). It takes the container (.gltf JSON, with external or data-URI
// buffers, or .glb) and checks its structure before any binary data is read: index
// references, accessor ranges against their bufferView and buffer, declared sizes against the
// actual data. Broken input throws signstim::InputError(file, line, field, message) with the
// glTF path of the offending field as a JSON pointer, as the Khronos glTF-Validator reports it
// (e.g. "/accessors/3/count"); nothing is ever read out of bounds.
//
// Also refused, as the Khronos glTF-Validator flags them: an extension in extensionsRequired
// (signstim implements none), negative byteOffsets, colour factors outside [0, 1], a texture
// sampled with a TEXCOORD_n set its primitive lacks, an animation without channels, a node
// with both a matrix and TRS, image/buffer URIs outside the model's folder (GltfLoadOptions).
//
// An accessor is checked completely (types, range, sparse part) and its values for NaN/Inf
// when it is read, through ValidatedGltf::readAccessor: an accessor nothing reads is never
// refused. Checks that need the values read or converted (index values against the vertex
// count, joints against their skin, the node graph) are the conversion's (gltf_loader.hpp).
//
// The validator stands alone, without Vulkan or a Scene, so it can be fuzzed by itself:
// validateGltfBytes takes the file's bytes.
#include <cstdint>
#include <filesystem>
#include <initializer_list>
#include <memory>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace signstim::render {

struct GltfLoadOptions {
    // Images and buffers must lie in the model's folder (absolute paths and ".." out of it are
    // refused: a downloaded model must not read the user's other files) or in one of these.
    std::vector<std::filesystem::path> allowedDirectories;
    // The flag that adds to allowedDirectories, named in the refusal ("--allow-dir"); empty:
    // the message suggests none.
    std::string allowFlag;
};

class ValidatedGltf;

// Reads and validates the .gltf or .glb file `path`. Errors name path.string() as the file.
// `warnings` (optional) receives notes about valid-but-unusual input, as "file: note".
ValidatedGltf validateGltf(const std::filesystem::path& path, const GltfLoadOptions& options,
                           std::vector<std::string>* warnings = nullptr);

// Validates the in-memory .gltf or .glb `bytes` as if they were the file `fileName` in
// `baseDirectory` (empty: the current directory): external URIs resolve against
// baseDirectory and must stay inside it (or options.allowedDirectories). `fileName` is the
// name errors and warnings give, as loadGltf(path) gives path.string(): with the file's bytes,
// fileName == path.string() and baseDirectory == path.parent_path(), every error is the same
// as validateGltf(path)'s.
ValidatedGltf validateGltfBytes(std::string bytes, const std::string& fileName,
                                const std::filesystem::path& baseDirectory, const GltfLoadOptions& options,
                                std::vector<std::string>* warnings = nullptr);

// A parsed glTF model whose structure has been validated: every index reference is in
// range, every buffer holds its declared bytes, every bufferView lies inside its buffer.
// Accessor data is read through readAccessor, which checks the accessor before reading.
class ValidatedGltf {
public:
    ValidatedGltf(ValidatedGltf&&) noexcept;
    ValidatedGltf& operator=(ValidatedGltf&&) noexcept;
    ~ValidatedGltf();

    // The name errors and warnings give (path.string(), or validateGltfBytes' fileName).
    const std::string& fileName() const { return fileName_; }
    // The tinygltf model (include <tiny_gltf.h> to use it). Images stored in bufferViews are
    // not decoded yet (their data was not checked when tinygltf parsed the file).
    tinygltf::Model& model() { return *model_; }
    const tinygltf::Model& model() const { return *model_; }

    // Throws InputError(fileName(), line, field, message).
    [[noreturn]] void fail(const std::string& field, const std::string& message, int line = 0) const;

    // The first byte of bufferView `viewIndex` (in range: checked during validation).
    const std::uint8_t* viewData(int viewIndex) const;

    struct ByteRange {
        const std::uint8_t* data = nullptr;  // first element; null: accessor without bufferView
        std::size_t stride = 0;
    };
    // Checks accessor `index` completely (types, ranges, sparse part) and returns where its
    // elements live.
    ByteRange checkAccessor(int index) const;

    // All components of accessor `index` (count * components values), sparse substitution
    // applied, normalized integers mapped to [0,1]/[-1,1]. Refuses types outside `types` and
    // component types outside `componentTypes` (empty: any), both TINYGLTF_TYPE_* and
    // TINYGLTF_COMPONENT_TYPE_* values, and non-finite values; `usedAs` (a JSON pointer)
    // says in the message what the accessor was read for.
    std::vector<double> readAccessor(int index, std::initializer_list<int> types,
                                     std::initializer_list<int> componentTypes, const std::string& usedAs) const;

private:
    ValidatedGltf(std::unique_ptr<tinygltf::Model> model, std::string fileName);
    friend ValidatedGltf validateGltf(const std::filesystem::path&, const GltfLoadOptions&,
                                      std::vector<std::string>*);
    friend ValidatedGltf validateGltfBytes(std::string, const std::string&, const std::filesystem::path&,
                                           const GltfLoadOptions&, std::vector<std::string>*);

    std::unique_ptr<tinygltf::Model> model_;
    std::string fileName_;
};

// Small helpers the conversion (gltf_loader.cpp) shares with the validator.
namespace gltf_detail {
// JSON pointer (RFC 6901), as the glTF-Validator reports: at("nodes", 3) == "/nodes/3".
std::string at(const std::string& array, std::size_t i);
// Components of a TINYGLTF_TYPE_* (SCALAR 1 ... MAT4 16; 0 if unknown) and its name.
int componentCount(int type);
const char* typeName(int type);
}  // namespace gltf_detail

}  // namespace signstim::render
