// glTF validation: container, JSON, structure, buffers and bufferViews (gltf_validate.hpp).
// The accessor reader is in gltf_accessors.cpp, the files a model names in gltf_files.cpp.
#include "renderer/gltf_validate.hpp"

#include "renderer/gltf_files.hpp"

#include "common/error.hpp"
#include "common/input_limits.hpp"

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

namespace signstim::render {
namespace fs = std::filesystem;
using nlohmann::json;

namespace gltf_detail {

std::string at(const std::string& array, std::size_t i) {
    // JSON pointer (RFC 6901), as the glTF-Validator reports: at("nodes", 3) == "/nodes/3".
    return (array.rfind('/', 0) == 0 ? array : "/" + array) + "/" + std::to_string(i);
}

}  // namespace gltf_detail

namespace {
using gltf_detail::at;
using gltf_detail::checkInsideAllowedFolders;
using gltf_detail::decodedUri;
using gltf_detail::readGltfFile;

constexpr std::uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;     // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;      // "BIN\0"

std::uint32_t readU32(const std::string& bytes, std::size_t offset) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + offset, 4);  // glb is little-endian, as is every target
    return v;
}

// Images inside bufferViews are decoded after validation (tinygltf would hand the decoder a
// pointer computed from unchecked offsets); URI images arrive as complete byte vectors.
bool deferBufferViewImages(tinygltf::Image* image, const int index, std::string* err,
                           std::string* warn, int width, int height, const unsigned char* bytes,
                           int size, void*) {
    if (image->bufferView >= 0) return true;
    return tinygltf::LoadImageData(image, index, err, warn, width, height, bytes, size, nullptr);
}

class Validator {
public:
    // `bytes`: the whole .gltf or .glb; `file`: its name in messages; `baseDirectory`: what
    // tinygltf resolves URIs against; the model's folder (where URIs must stay) is
    // `location`'s parent folder if `locationIsFile`, else `location` itself.
    Validator(std::string bytes, std::string file, fs::path baseDirectory, fs::path location, bool locationIsFile,
              const GltfLoadOptions& options, std::vector<std::string>* warnings)
        : bytes_(std::move(bytes)), file_(std::move(file)), baseDirectory_(std::move(baseDirectory)),
          location_(std::move(location)), locationIsFile_(locationIsFile), options_(options), warnings_(warnings),
          model_(std::make_unique<tinygltf::Model>()) {}

    std::unique_ptr<tinygltf::Model> validate() {
        if (bytes_.empty()) fail("", "file is empty");
        parseContainer();
        precheckJson();
        parseWithTinyGltf();
        validateBuffersAndViews();
        return std::move(model_);
    }

private:
    [[noreturn]] void fail(const std::string& field, const std::string& message, int line = 0) const {
        throw InputError(file_, line, field, message);
    }
    void warn(const std::string& message) {
        if (warnings_) warnings_->push_back(file_ + ": " + message);
    }

    // The model's folder, absolute (not yet canonical).
    fs::path modelFolder() const {
        return locationIsFile_ ? fs::absolute(location_).parent_path() : fs::absolute(location_);
    }

    // ---- container -----------------------------------------------------------------------
    void parseContainer() {
        if (bytes_.size() >= 4 && readU32(bytes_, 0) == kGlbMagic) {
            isGlb_ = true;
            const std::size_t size = bytes_.size();
            if (size < 20)
                fail("", "truncated .glb: " + std::to_string(size) +
                             " bytes, the header and first chunk header need 20");
            const std::uint32_t version = readU32(bytes_, 4);
            if (version != 2)
                fail("glb.version", "unsupported GLB container version " + std::to_string(version) +
                                        " (glTF 2.0 needs 2)");
            const std::uint64_t length = readU32(bytes_, 8);
            if (length > size)
                fail("glb.length", "truncated .glb: header declares " + std::to_string(length) +
                                       " bytes but the file has " + std::to_string(size));
            const std::uint64_t jsonLength = readU32(bytes_, 12);
            if (readU32(bytes_, 16) != kChunkJson) fail("glb.chunks[0]", "first chunk is not JSON");
            if (jsonLength == 0 || 20 + jsonLength > length)
                fail("glb.chunks[0].chunkLength",
                     "truncated .glb: JSON chunk of " + std::to_string(jsonLength) +
                         " bytes does not fit in the " + std::to_string(length) + "-byte file");
            jsonText_ = bytes_.substr(20, jsonLength);
            const std::uint64_t next = 20 + jsonLength;
            if (next + 8 <= length) {
                const std::uint64_t binLength = readU32(bytes_, next);
                if (readU32(bytes_, next + 4) == kChunkBin) {
                    if (next + 8 + binLength > length)
                        fail("glb.chunks[1].chunkLength",
                             "truncated .glb: BIN chunk of " + std::to_string(binLength) +
                                 " bytes does not fit in the " + std::to_string(length) + "-byte file");
                    hasBin_ = true;
                    binLength_ = binLength;
                }
            } else if (next != length) {
                fail("glb.length", "truncated .glb: " + std::to_string(length - next) +
                                       " stray bytes after the JSON chunk");
            }
        } else {
            jsonText_ = bytes_;
        }
        // Depth first: a file of 10^5 nested arrays would otherwise be built, and torn down,
        // by recursion (common/input_limits.hpp; docs/errors.md, "Limits").
        struct TooDeep {};
        try {
            root_ = json::parse(jsonText_, [](int depth, json::parse_event_t, json&) {
                if (static_cast<std::size_t>(depth) > limits::kJsonDepth) throw TooDeep{};
                return true;
            });
        } catch (const TooDeep&) {
            fail("", "not a glTF file: arrays and objects nested more than " + std::to_string(limits::kJsonDepth) +
                         " deep (docs/errors.md, \"Limits\")");
        } catch (const json::parse_error& e) {
            int line = 0;
            if (!isGlb_) {
                const std::size_t end = std::min<std::size_t>(e.byte, jsonText_.size());
                line = 1 + static_cast<int>(std::count(jsonText_.begin(),
                                                       jsonText_.begin() + static_cast<long>(end), '\n'));
            }
            fail("", "not a glTF file: invalid JSON at byte " + std::to_string(e.byte) +
                         (isGlb_ ? " of the JSON chunk" : ""), line);
        } catch (const json::out_of_range& e) {
            // 406: a number beyond a double ("1e400"). nlohmann gives no position, only the
            // literal: its first occurrence gives the byte and line (found by the fuzzer: it
            // was an internal error, exit 4).
            const std::string what = e.what();
            const std::size_t open = what.find('\''), close = what.rfind('\'');
            const std::string literal = open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
            const std::size_t byte = literal.empty() ? std::string::npos : jsonText_.find(literal);
            int line = 0;
            if (!isGlb_ && byte != std::string::npos)
                line = 1 + static_cast<int>(std::count(jsonText_.begin(), jsonText_.begin() + static_cast<long>(byte), '\n'));
            fail("", "not a glTF file: the number " + (literal.empty() ? std::string("") : "'" + literal + "' ") +
                         (byte != std::string::npos ? "at byte " + std::to_string(byte) + (isGlb_ ? " of the JSON chunk " : " ") : "") +
                         "does not fit a double (at most about 1.8e308 in size)", line);
        }
        if (!root_.is_object()) fail("", "not a glTF file: the JSON top level is not an object");
        const auto asset = root_.find("asset");
        if (asset == root_.end() || !asset->is_object()) fail("/asset", "missing (not a glTF 2.0 file?)");
        const auto version = asset->find("version");
        if (version == asset->end() || !version->is_string() ||
            version->get<std::string>().rfind("2.", 0) != 0)
            fail("/asset/version", "not a glTF 2.x file (version must be \"2.0\")");
    }


    // ---- JSON-level checks: every index reference in range, declared sizes plausible -------
    std::size_t arraySize(const char* name) const {
        const auto it = root_.find(name);
        return it != root_.end() && it->is_array() ? it->size() : 0;
    }

    const json& array(const char* name) {
        static const json empty = json::array();
        const auto it = root_.find(name);
        if (it == root_.end()) return empty;
        if (!it->is_array()) fail(std::string("/") + name, "must be an array");
        for (std::size_t i = 0; i < it->size(); ++i)
            if (!(*it)[i].is_object()) fail(at(name, i), "must be an object");
        return *it;
    }

    void checkIndex(const json& object, const char* key, const char* target, std::size_t count,
                    const std::string& field, bool required = false) {
        const auto it = object.find(key);
        if (it == object.end()) {
            if (required) fail(field + "/" + key, "is required");
            return;
        }
        checkIndexValue(*it, target, count, field + "/" + key);
    }
    void checkIndexValue(const json& value, const char* target, std::size_t count,
                         const std::string& field) {
        if (!value.is_number_integer() || value.get<std::int64_t>() < 0)
            fail(field, "must be a non-negative integer index into " + std::string(target));
        const auto index = value.get<std::uint64_t>();
        if (index >= count)
            fail(field, "index " + std::to_string(index) + " out of range: " + target + " has " +
                            std::to_string(count) + " entr" + (count == 1 ? "y" : "ies"));
    }
    void checkIndexArray(const json& object, const char* key, const char* target, std::size_t count,
                         const std::string& field) {
        const auto it = object.find(key);
        if (it == object.end()) return;
        if (!it->is_array()) fail(field + "/" + key, "must be an array");
        for (std::size_t i = 0; i < it->size(); ++i)
            checkIndexValue((*it)[i], target, count, at(field + "/" + key, i));
    }
    void checkTextureInfo(const json& parent, const char* key, const std::string& field) {
        const auto it = parent.find(key);
        if (it == parent.end()) return;
        if (!it->is_object()) fail(field + "/" + key, "must be an object");
        checkIndex(*it, "index", "textures", arraySize("textures"), field + "/" + key, true);
    }
    std::uint64_t positiveInteger(const json& object, const char* key, const std::string& field) {
        const auto it = object.find(key);
        if (it == object.end()) fail(field + "/" + key, "is required");
        if (!it->is_number_integer() || it->get<std::int64_t>() < 1)
            fail(field + "/" + key, "must be a positive integer");
        return it->get<std::uint64_t>();
    }

    // An optional byte offset: a non-negative integer (glTF 2.0 schema: minimum 0). tinygltf
    // stores offsets unsigned, so a negative one would wrap round to a huge value.
    void nonNegativeOffset(const json& object, const std::string& field) {
        const auto it = object.find("byteOffset");
        if (it == object.end()) return;
        if (!it->is_number_integer() || it->get<std::int64_t>() < 0)
            fail(field + "/byteOffset", "must be a non-negative integer, got " + it->dump());
    }

    // An optional array of `size` numbers in [0, 1] (colour factors, glTF 2.0 material schema).
    void unitFactors(const json& object, const char* key, std::size_t size, const std::string& field) {
        const auto it = object.find(key);
        if (it == object.end()) return;
        bool ok = it->is_array() && it->size() == size;
        for (std::size_t i = 0; ok && i < size; ++i)
            ok = (*it)[i].is_number() && (*it)[i].get<double>() >= 0.0 && (*it)[i].get<double>() <= 1.0;
        if (!ok)
            fail(field + "/" + key, "must be " + std::to_string(size) + " numbers in [0, 1], got " + it->dump());
    }

    // glTF 2.0 §3.12: a file listing an extension in extensionsRequired cannot be shown
    // correctly without it, and a loader that does not implement it must refuse the file.
    // signstim implements no extension.
    void refuseRequiredExtensions() {
        const auto it = root_.find("extensionsRequired");
        if (it == root_.end()) return;
        if (!it->is_array()) fail("/extensionsRequired", "must be an array of extension names");
        for (std::size_t i = 0; i < it->size(); ++i) {
            const std::string name = (*it)[i].is_string() ? (*it)[i].get<std::string>() : (*it)[i].dump();
            fail(at("extensionsRequired", i), "the file requires the extension " + name +
                                                   ", which signstim does not implement (a glTF loader must "
                                                   "refuse such a file; export the model without it)");
        }
    }

    // Every texture a primitive's material samples names a TEXCOORD_n set the primitive has
    // (glTF-Validator: MESH_PRIMITIVE_TOO_FEW_TEXCOORDS); without it the texture has no
    // coordinates to be sampled at.
    void checkTextureCoordinateSets(const json& meshArray, const json& materialArray) {
        for (std::size_t m = 0; m < meshArray.size(); ++m) {
            const json& prims = meshArray[m]["primitives"];
            for (std::size_t p = 0; p < prims.size(); ++p) {
                const json& prim = prims[p];
                const auto material = prim.find("material");
                if (material == prim.end()) continue;
                const std::size_t index = material->get<std::size_t>();
                const std::string mf = at("materials", index);
                const json& mat = materialArray[index];
                std::vector<std::pair<const json*, std::string>> infos;
                for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"})
                    if (mat.contains(key)) infos.emplace_back(&mat[key], mf + "/" + key);
                if (const auto pbr = mat.find("pbrMetallicRoughness"); pbr != mat.end() && pbr->is_object())
                    for (const char* key : {"baseColorTexture", "metallicRoughnessTexture"})
                        if (pbr->contains(key)) infos.emplace_back(&(*pbr)[key], mf + "/pbrMetallicRoughness/" + key);
                for (const auto& [info, field] : infos) {
                    std::int64_t set = 0;
                    if (const auto texCoord = info->find("texCoord"); texCoord != info->end()) {
                        if (!texCoord->is_number_integer() || texCoord->get<std::int64_t>() < 0)
                            fail(field + "/texCoord", "must be a non-negative integer, got " + texCoord->dump());
                        set = texCoord->get<std::int64_t>();
                    }
                    const std::string attribute = "TEXCOORD_" + std::to_string(set);
                    if (!prim["attributes"].contains(attribute))
                        fail(field + "/texCoord",
                             "the texture is sampled with " + attribute + ", but " +
                                 at(at("meshes", m) + "/primitives", p) +
                                 " (which uses this material) has no such attribute");
                }
            }
        }
    }

    void precheckJson() {
        refuseRequiredExtensions();
        const std::size_t nodes = arraySize("nodes"), meshes = arraySize("meshes"),
                          accessors = arraySize("accessors"), views = arraySize("bufferViews"),
                          buffers = arraySize("buffers"), skins = arraySize("skins"),
                          materials = arraySize("materials"), textures = arraySize("textures"),
                          images = arraySize("images"), samplers = arraySize("samplers"),
                          scenes = arraySize("scenes"), cameras = arraySize("cameras");
        if (root_.contains("scene")) checkIndexValue(root_["scene"], "scenes", scenes, "/scene");
        const json& sceneArray = array("scenes");
        for (std::size_t i = 0; i < sceneArray.size(); ++i)
            checkIndexArray(sceneArray[i], "nodes", "nodes", nodes, at("scenes", i));
        const json& nodeArray = array("nodes");
        for (std::size_t i = 0; i < nodeArray.size(); ++i) {
            const std::string f = at("nodes", i);
            checkIndexArray(nodeArray[i], "children", "nodes", nodes, f);
            checkIndex(nodeArray[i], "mesh", "meshes", meshes, f);
            checkIndex(nodeArray[i], "skin", "skins", skins, f);
            checkIndex(nodeArray[i], "camera", "cameras", cameras, f);
            // glTF 2.0 §3.5.3: a node has a matrix or TRS properties, never both (which one
            // would win is undefined).
            if (nodeArray[i].contains("matrix"))
                for (const char* key : {"translation", "rotation", "scale"})
                    if (nodeArray[i].contains(key))
                        fail(f, std::string("has both matrix and ") + key +
                                    " (glTF 2.0 allows a matrix or translation/rotation/scale, not both)");
        }
        const json& meshArray = array("meshes");
        for (std::size_t m = 0; m < meshArray.size(); ++m) {
            const auto prims = meshArray[m].find("primitives");
            if (prims == meshArray[m].end() || !prims->is_array() || prims->empty())
                fail(at("meshes", m) + "/primitives", "must be a non-empty array");
            for (std::size_t p = 0; p < prims->size(); ++p) {
                const json& prim = (*prims)[p];
                const std::string f = at(at("meshes", m) + "/primitives", p);
                if (!prim.is_object()) fail(f, "must be an object");
                const auto attributes = prim.find("attributes");
                if (attributes == prim.end() || !attributes->is_object())
                    fail(f + "/attributes", "must be an object");
                for (const auto& [name, value] : attributes->items())
                    checkIndexValue(value, "accessors", accessors, f + "/attributes/" + name);
                checkIndex(prim, "indices", "accessors", accessors, f);
                checkIndex(prim, "material", "materials", materials, f);
                if (const auto targets = prim.find("targets"); targets != prim.end() && targets->is_array())
                    for (std::size_t t = 0; t < targets->size(); ++t)
                        if ((*targets)[t].is_object())
                            for (const auto& [name, value] : (*targets)[t].items())
                                checkIndexValue(value, "accessors", accessors,
                                                at(f + "/targets", t) + "/" + name);
            }
        }
        const json& accessorArray = array("accessors");
        for (std::size_t i = 0; i < accessorArray.size(); ++i) {
            const std::string f = at("accessors", i);
            checkIndex(accessorArray[i], "bufferView", "bufferViews", views, f);
            nonNegativeOffset(accessorArray[i], f);
            positiveInteger(accessorArray[i], "count", f);
            if (const auto sparse = accessorArray[i].find("sparse"); sparse != accessorArray[i].end()) {
                if (!sparse->is_object()) fail(f + "/sparse", "must be an object");
                for (const char* part : {"indices", "values"}) {
                    const auto it = sparse->find(part);
                    if (it == sparse->end() || !it->is_object())
                        fail(f + "/sparse/" + part, "is required");
                    checkIndex(*it, "bufferView", "bufferViews", views, f + "/sparse/" + part, true);
                    nonNegativeOffset(*it, f + "/sparse/" + part);
                }
                positiveInteger(*sparse, "count", f + "/sparse");
            }
        }
        const json& viewArray = array("bufferViews");
        for (std::size_t i = 0; i < viewArray.size(); ++i) {
            checkIndex(viewArray[i], "buffer", "buffers", buffers, at("bufferViews", i), true);
            positiveInteger(viewArray[i], "byteLength", at("bufferViews", i));
            nonNegativeOffset(viewArray[i], at("bufferViews", i));
        }
        const json& bufferArray = array("buffers");
        for (std::size_t i = 0; i < bufferArray.size(); ++i) precheckBuffer(bufferArray[i], i);
        const json& skinArray = array("skins");
        for (std::size_t i = 0; i < skinArray.size(); ++i) {
            const std::string f = at("skins", i);
            const auto joints = skinArray[i].find("joints");
            if (joints == skinArray[i].end() || !joints->is_array() || joints->empty())
                fail(f + "/joints", "must be a non-empty array of node indices");
            checkIndexArray(skinArray[i], "joints", "nodes", nodes, f);
            checkIndex(skinArray[i], "skeleton", "nodes", nodes, f);
            checkIndex(skinArray[i], "inverseBindMatrices", "accessors", accessors, f);
        }
        const json& animationArray = array("animations");
        for (std::size_t a = 0; a < animationArray.size(); ++a) {
            const std::string f = at("animations", a);
            const json& animation = animationArray[a];
            const auto samplerList = animation.find("samplers");
            const auto channelList = animation.find("channels");
            // glTF 2.0 schema: both arrays have at least one item (an animation that
            // animates nothing is an error in the glTF-Validator, not an empty clip).
            if (samplerList == animation.end() || !samplerList->is_array() || samplerList->empty())
                fail(f + "/samplers", "must be a non-empty array");
            if (channelList == animation.end() || !channelList->is_array() || channelList->empty())
                fail(f + "/channels", "must be a non-empty array (an animation without channels animates nothing)");
            for (std::size_t s = 0; s < samplerList->size(); ++s) {
                const json& sampler = (*samplerList)[s];
                if (!sampler.is_object()) fail(at(f + "/samplers", s), "must be an object");
                checkIndex(sampler, "input", "accessors", accessors, at(f + "/samplers", s), true);
                checkIndex(sampler, "output", "accessors", accessors, at(f + "/samplers", s), true);
            }
            for (std::size_t c = 0; c < channelList->size(); ++c) {
                const json& channel = (*channelList)[c];
                const std::string cf = at(f + "/channels", c);
                if (!channel.is_object()) fail(cf, "must be an object");
                checkIndex(channel, "sampler", (f + "/samplers").c_str(), samplerList->size(), cf, true);
                const auto target = channel.find("target");
                if (target == channel.end() || !target->is_object()) fail(cf + "/target", "is required");
                checkIndex(*target, "node", "nodes", nodes, cf + "/target");
            }
        }
        const json& materialArray = array("materials");
        for (std::size_t i = 0; i < materialArray.size(); ++i) {
            const std::string f = at("materials", i);
            const json& material = materialArray[i];
            if (const auto pbr = material.find("pbrMetallicRoughness"); pbr != material.end() && pbr->is_object()) {
                checkTextureInfo(*pbr, "baseColorTexture", f + "/pbrMetallicRoughness");
                checkTextureInfo(*pbr, "metallicRoughnessTexture", f + "/pbrMetallicRoughness");
                unitFactors(*pbr, "baseColorFactor", 4, f + "/pbrMetallicRoughness");
            }
            for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"})
                checkTextureInfo(material, key, f);
            unitFactors(material, "emissiveFactor", 3, f);
        }
        checkTextureCoordinateSets(meshArray, materialArray);
        const json& textureArray = array("textures");
        for (std::size_t i = 0; i < textureArray.size(); ++i) {
            checkIndex(textureArray[i], "source", "images", images, at("textures", i));
            checkIndex(textureArray[i], "sampler", "samplers", samplers, at("textures", i));
        }
        (void)textures;
        const json& imageArray = array("images");
        for (std::size_t i = 0; i < imageArray.size(); ++i) {
            const std::string f = at("images", i);
            checkIndex(imageArray[i], "bufferView", "bufferViews", views, f);
            const auto uri = imageArray[i].find("uri");
            if (uri != imageArray[i].end()) {
                if (!uri->is_string()) fail(f + "/uri", "must be a string");
                checkExternalFile(uri->get<std::string>(), f + "/uri");
            } else if (!imageArray[i].contains("bufferView")) {
                fail(f, "needs either uri or bufferView");
            }
        }
    }

    // External file named by a uri (relative to the glTF file). Returns its size; 0 for
    // data URIs.
    std::uint64_t checkExternalFile(const std::string& uri, const std::string& field) {
        if (uri.rfind("data:", 0) == 0) return 0;
        if (uri.find("://") != std::string::npos)
            fail(field, "remote resources are not supported: " + uri);
        const fs::path file = checkInsideAllowedFolders(decodedUri(uri), uri, field, modelFolder(), options_, file_);
        std::error_code ec;
        if (!fs::is_regular_file(file, ec))
            fail(field, "referenced file '" + file.string() + "' not found");
        const std::uint64_t size = fs::file_size(file, ec);
        if (ec) fail(field, "cannot read referenced file '" + file.string() + "'");
        return size;
    }

    void precheckBuffer(const json& buffer, std::size_t i) {
        const std::string f = at("buffers", i);
        const std::uint64_t byteLength = positiveInteger(buffer, "byteLength", f);
        const auto uri = buffer.find("uri");
        if (uri == buffer.end()) {
            if (!isGlb_ || i != 0 || !hasBin_)
                fail(f + "/uri", "is required (only the first buffer of a .glb may use the BIN chunk)");
            if (byteLength > binLength_)
                fail(f + "/byteLength", "byteLength " + std::to_string(byteLength) +
                                            " exceeds the " + std::to_string(binLength_) +
                                            " bytes of the GLB binary chunk");
            return;
        }
        if (!uri->is_string()) fail(f + "/uri", "must be a string");
        const std::string text = uri->get<std::string>();
        if (text.rfind("data:", 0) == 0) {
            const std::size_t comma = text.find(',');
            if (comma == std::string::npos || text.find(";base64", 0) > comma)
                fail(f + "/uri", "data URI must be base64 encoded (data:...;base64,...)");
            std::uint64_t payload = text.size() - comma - 1;
            std::uint64_t decoded = payload / 4 * 3;
            if (payload >= 1 && text.back() == '=') --decoded;
            if (payload >= 2 && text[text.size() - 2] == '=') --decoded;
            if (byteLength != decoded)  // tinygltf needs an exact match for data URIs
                fail(f + "/byteLength", "byteLength " + std::to_string(byteLength) +
                                            (byteLength > decoded ? " exceeds the " : " does not match the ") +
                                            std::to_string(decoded) + " bytes of the embedded data URI");
            return;
        }
        const std::uint64_t size = checkExternalFile(text, f + "/uri");
        if (byteLength > size)
            fail(f + "/byteLength", "byteLength " + std::to_string(byteLength) + " exceeds the " +
                                        std::to_string(size) + " bytes of '" + text + "'");
    }

    void parseWithTinyGltf() {
        tinygltf::TinyGLTF gltf;
        gltf.SetImageLoader(deferBufferViewImages, nullptr);
        std::string err, warn;
        bool ok = false;
        const std::string baseDir = baseDirectory_.string();
        try {
            if (isGlb_)
                ok = gltf.LoadBinaryFromMemory(model_.get(), &err, &warn,
                                               reinterpret_cast<const unsigned char*>(bytes_.data()),
                                               static_cast<unsigned int>(bytes_.size()), baseDir);
            else
                ok = gltf.LoadASCIIFromString(model_.get(), &err, &warn, bytes_.data(),
                                              static_cast<unsigned int>(bytes_.size()), baseDir);
        } catch (const std::exception& e) {
            fail("", std::string("glTF parse error: ") + e.what());
        }
        auto trim = [](std::string s) {
            while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
            return s;
        };
        if (!ok) fail("", "glTF parse error: " + trim(err.empty() ? warn : err));
        // tinygltf 2.7 reports the optional skins[].inverseBindMatrices as a missing required
        // property while loading successfully: a warning, not an error.
        for (const std::string* text : {&err, &warn}) {
            std::istringstream lines(*text);
            for (std::string line; std::getline(lines, line);)
                if (!line.empty()) this->warn(line);
        }
    }

    // ---- binary data ------------------------------------------------------------------------
    void validateBuffersAndViews() {
        for (std::size_t i = 0; i < model_->buffers.size(); ++i) {
            // Size agreement was checked before loading; tinygltf may pad, never shrink.
            if (model_->buffers[i].data.size() < static_cast<std::size_t>(root_["buffers"][i]["byteLength"].get<std::uint64_t>()))
                fail(at("buffers", i) + "/byteLength", "declares more bytes than the buffer holds");
        }
        for (std::size_t i = 0; i < model_->bufferViews.size(); ++i) {
            const tinygltf::BufferView& view = model_->bufferViews[i];
            const std::string f = at("bufferViews", i);
            const std::uint64_t bufferSize = model_->buffers[static_cast<std::size_t>(view.buffer)].data.size();
            if (view.byteLength > bufferSize || view.byteOffset > bufferSize - view.byteLength)
                fail(f + "/byteLength", "range [" + std::to_string(view.byteOffset) + ", " +
                                            std::to_string(static_cast<std::uint64_t>(view.byteOffset) + view.byteLength) +
                                            ") reads past the end of /buffers/" + std::to_string(view.buffer) +
                                            " (" + std::to_string(bufferSize) + " bytes)");
            if (view.byteStride != 0 && (view.byteStride < 4 || view.byteStride > 252 || view.byteStride % 4 != 0))
                fail(f + "/byteStride", "must be a multiple of 4 in [4, 252], got " +
                                            std::to_string(view.byteStride));
        }
    }

    std::string bytes_;
    std::string file_;
    fs::path baseDirectory_;
    fs::path location_;
    bool locationIsFile_;
    GltfLoadOptions options_;
    std::vector<std::string>* warnings_;
    std::string jsonText_;
    bool isGlb_ = false, hasBin_ = false;
    std::uint64_t binLength_ = 0;
    json root_;
    std::unique_ptr<tinygltf::Model> model_;
};

}  // namespace

// ---- entry points ---------------------------------------------------------------------------
ValidatedGltf validateGltf(const fs::path& path, const GltfLoadOptions& options, std::vector<std::string>* warnings) {
    const std::string file = path.string();
    Validator validator(readGltfFile(path, file), file, path.parent_path(), path, true, options, warnings);
    return ValidatedGltf(validator.validate(), file);
}

ValidatedGltf validateGltfBytes(std::string bytes, const std::string& fileName, const fs::path& baseDirectory,
                                const GltfLoadOptions& options, std::vector<std::string>* warnings) {
    const fs::path folder = baseDirectory.empty() ? fs::path(".") : baseDirectory;
    Validator validator(std::move(bytes), fileName, baseDirectory, folder, false, options, warnings);
    return ValidatedGltf(validator.validate(), fileName);
}

}  // namespace signstim::render
