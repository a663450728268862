#include "renderer/gltf_writer.hpp"

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "renderer/image_io.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace signstim::render {
namespace {

using nlohmann::json;

constexpr int kFloat = 5126, kUnsignedShort = 5123, kUnsignedInt = 5125;

std::string base64(const std::vector<std::uint8_t>& data) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((data.size() + 2) / 3 * 4);
    std::size_t i = 0;
    for (; i + 2 < data.size(); i += 3) {
        const std::uint32_t v = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += table[(v >> 6) & 63];
        out += table[v & 63];
    }
    if (i + 1 == data.size()) {
        const std::uint32_t v = data[i] << 16;
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += "==";
    } else if (i + 2 == data.size()) {
        const std::uint32_t v = (data[i] << 16) | (data[i + 1] << 8);
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += table[(v >> 6) & 63];
        out += '=';
    }
    return out;
}

json floats(const float* v, int n) {
    json a = json::array();
    for (int i = 0; i < n; ++i) a.push_back(v[i]);
    return a;
}

class Writer {
public:
    explicit Writer(const Scene& scene) : scene_(scene) {}

    json build() {
        doc_["asset"] = {{"version", "2.0"}, {"generator", "signstim"}};
        writeImagesAndTextures();
        writeMaterials();
        writeMeshes();
        writeNodes();
        writeSkins();
        writeAnimations();
        doc_["scenes"] = json::array({json{{"nodes", scene_.roots}}});
        doc_["scene"] = 0;
        if (!bin_.empty()) doc_["buffers"] = json::array({json{{"byteLength", bin_.size()}}});
        return doc_;
    }
    const std::vector<std::uint8_t>& bin() const { return bin_; }

private:
    int addView(const void* data, std::size_t size, int target = 0) {
        while (bin_.size() % 4) bin_.push_back(0);
        const std::size_t offset = bin_.size();
        bin_.resize(offset + size);
        if (size) std::memcpy(bin_.data() + offset, data, size);
        json view = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", size}};
        if (target) view["target"] = target;
        doc_["bufferViews"].push_back(view);
        return static_cast<int>(doc_["bufferViews"].size()) - 1;
    }
    template <typename T>
    int addAccessor(const std::vector<T>& values, int componentType, int components, const char* type,
                    int target = 0, bool minMax = false, bool normalized = false) {
        const std::size_t count = values.size() / static_cast<std::size_t>(components);
        json a = {{"bufferView", addView(values.data(), values.size() * sizeof(T), target)},
                  {"componentType", componentType}, {"count", count}, {"type", type}};
        if (normalized) a["normalized"] = true;
        if (minMax && count > 0) {  // required for POSITION and animation input
            json lo = json::array(), hi = json::array();
            for (int c = 0; c < components; ++c) {
                T mn = values[static_cast<std::size_t>(c)], mx = mn;
                for (std::size_t e = 1; e < count; ++e) {
                    mn = std::min(mn, values[e * components + c]);
                    mx = std::max(mx, values[e * components + c]);
                }
                lo.push_back(mn);
                hi.push_back(mx);
            }
            a["min"] = lo;
            a["max"] = hi;
        }
        doc_["accessors"].push_back(a);
        return static_cast<int>(doc_["accessors"].size()) - 1;
    }

    int addMorphAccessor(const std::vector<glm::vec3>& d, bool minMax) {
        std::vector<std::uint32_t> moved;
        std::vector<float> values;
        for (std::size_t v = 0; v < d.size(); ++v)
            if (d[v] != glm::vec3(0.0f)) {
                moved.push_back(static_cast<std::uint32_t>(v));
                values.insert(values.end(), {d[v].x, d[v].y, d[v].z});
            }
        if (moved.size() * 16 >= d.size() * 12) {  // sparse would be larger: dense
            std::vector<float> dense;
            for (const glm::vec3& x : d) dense.insert(dense.end(), {x.x, x.y, x.z});
            return addAccessor(dense, kFloat, 3, "VEC3", 34962, minMax);
        }
        // No bufferView: zeros, overridden by the sparse values (none when nothing moves).
        json a = {{"componentType", kFloat}, {"count", d.size()}, {"type", "VEC3"}};
        if (minMax && !d.empty()) {
            glm::vec3 lo(0.0f), hi(0.0f);  // some element is an implicit zero
            for (const glm::vec3& x : d) {
                lo = glm::min(lo, x);
                hi = glm::max(hi, x);
            }
            a["min"] = {lo.x, lo.y, lo.z};
            a["max"] = {hi.x, hi.y, hi.z};
        }
        if (!moved.empty()) {
            a["sparse"] = {{"count", moved.size()},
                           {"indices", {{"bufferView", addView(moved.data(), moved.size() * sizeof(std::uint32_t))},
                                        {"componentType", kUnsignedInt}}},
                           {"values", {{"bufferView", addView(values.data(), values.size() * sizeof(float))}}}};
        }
        doc_["accessors"].push_back(a);
        return static_cast<int>(doc_["accessors"].size()) - 1;
    }

    void writeImagesAndTextures() {
        for (const ImageData& image : scene_.images) {
            Image pixels;
            pixels.width = image.width;
            pixels.height = image.height;
            pixels.bytes = image.rgba;
            ImageWriteOptions options;
            options.pngCompression = 6;  // written once, read often: smaller is worth it
            const std::vector<std::uint8_t> png = encodePng(pixels, options);
            json out = {{"bufferView", addView(png.data(), png.size())}, {"mimeType", "image/png"}};
            if (!image.name.empty()) out["name"] = image.name;
            doc_["images"].push_back(out);
        }
        for (const Texture& texture : scene_.textures) {
            auto wrap = [](Wrap w) { return w == Wrap::Repeat ? 10497 : w == Wrap::ClampToEdge ? 33071 : 33648; };
            const int nearest = 9728, linear = 9729;
            int minFilter = texture.minFilter == Filter::Nearest ? nearest : linear;
            if (texture.mipmaps) minFilter = texture.minFilter == Filter::Nearest ? 9986 : 9987;  // *_MIPMAP_LINEAR
            doc_["samplers"].push_back({{"magFilter", texture.magFilter == Filter::Nearest ? nearest : linear},
                                        {"minFilter", minFilter},
                                        {"wrapS", wrap(texture.wrapS)},
                                        {"wrapT", wrap(texture.wrapT)}});
            json out = {{"sampler", doc_["samplers"].size() - 1}};
            if (texture.image >= 0) out["source"] = texture.image;
            doc_["textures"].push_back(out);
        }
    }

    void writeMaterials() {
        for (const Material& m : scene_.materials) {
            json pbr = {{"baseColorFactor", floats(&m.baseColorFactor[0], 4)},
                        {"metallicFactor", m.metallicFactor},
                        {"roughnessFactor", m.roughnessFactor}};
            if (m.baseColorTexture >= 0) pbr["baseColorTexture"] = {{"index", m.baseColorTexture}};
            if (m.metallicRoughnessTexture >= 0) pbr["metallicRoughnessTexture"] = {{"index", m.metallicRoughnessTexture}};
            json out = {{"pbrMetallicRoughness", pbr}, {"emissiveFactor", floats(&m.emissiveFactor[0], 3)},
                        {"alphaMode", m.alphaMode == AlphaMode::Opaque ? "OPAQUE" : m.alphaMode == AlphaMode::Mask ? "MASK" : "BLEND"},
                        {"doubleSided", m.doubleSided}};
            if (m.alphaMode == AlphaMode::Mask) out["alphaCutoff"] = m.alphaCutoff;
            if (!m.name.empty()) out["name"] = m.name;
            doc_["materials"].push_back(out);
        }
    }

    void writeMeshes() {
        constexpr int arrayBuffer = 34962, elementArrayBuffer = 34963;
        for (const Mesh& mesh : scene_.meshes) {
            json primitives = json::array();
            for (const Primitive& p : mesh.primitives) {
                std::vector<float> positions, normals, uvs, weights;
                std::vector<std::uint16_t> joints;
                for (const Vertex& v : p.vertices) {
                    positions.insert(positions.end(), {v.position.x, v.position.y, v.position.z});
                    normals.insert(normals.end(), {v.normal.x, v.normal.y, v.normal.z});
                    uvs.insert(uvs.end(), {v.uv.x, v.uv.y});
                    if (p.skinned) {
                        for (int k = 0; k < 4; ++k) {
                            if (v.joints[k] > 65535) throw std::invalid_argument("writeGltf: joint index above 65535");
                            joints.push_back(static_cast<std::uint16_t>(v.joints[k]));
                        }
                        weights.insert(weights.end(), {v.weights.x, v.weights.y, v.weights.z, v.weights.w});
                    }
                }
                for (std::uint32_t index : p.indices)
                    if (index >= p.vertices.size()) throw std::invalid_argument("writeGltf: index past vertex count");
                json attributes = {{"POSITION", addAccessor(positions, kFloat, 3, "VEC3", arrayBuffer, true)},
                                   {"NORMAL", addAccessor(normals, kFloat, 3, "VEC3", arrayBuffer)},
                                   {"TEXCOORD_0", addAccessor(uvs, kFloat, 2, "VEC2", arrayBuffer)}};
                if (p.skinned) {
                    attributes["JOINTS_0"] = addAccessor(joints, kUnsignedShort, 4, "VEC4", arrayBuffer);
                    attributes["WEIGHTS_0"] = addAccessor(weights, kFloat, 4, "VEC4", arrayBuffer);
                }
                json out = {{"attributes", attributes}, {"mode", 4}};
                if (!p.indices.empty()) out["indices"] = addAccessor(p.indices, kUnsignedInt, 1, "SCALAR", elementArrayBuffer);
                if (p.material >= 0) out["material"] = p.material;
                if (!p.targets.empty()) out["targets"] = morphTargets(p);
                primitives.push_back(out);
            }
            json out = {{"primitives", primitives}};
            if (!mesh.name.empty()) out["name"] = mesh.name;
            if (mesh.targetCount() > 0 && mesh.weights.size() == mesh.targetCount()) out["weights"] = mesh.weights;
            if (mesh.targetCount() > 0 && mesh.targetNames.size() == mesh.targetCount())
                out["extras"] = {{"targetNames", mesh.targetNames}};  // the exporters' convention
            doc_["meshes"].push_back(out);
        }
    }

    // POSITION (with the min/max glTF requires) and NORMAL displacements per target: sparse
    // (glTF 2.0 §3.6.2.3) where most vertices do not move — a face's targets move a few
    // hundred of a body's vertices — dense otherwise.
    json morphTargets(const Primitive& p) {
        json targets = json::array();
        for (const MorphTarget& target : p.targets) {
            json out = json::object();
            for (const auto* attribute : {&target.position, &target.normal}) {
                if (attribute->empty()) continue;
                if (attribute->size() != p.vertices.size())
                    throw std::invalid_argument("writeGltf: a morph target does not cover every vertex");
                const bool position = attribute == &target.position;
                out[position ? "POSITION" : "NORMAL"] = addMorphAccessor(*attribute, position);
            }
            targets.push_back(out);
        }
        return targets;
    }

    void writeNodes() {
        for (const Node& node : scene_.nodes) {
            json out = json::object();
            if (!node.name.empty()) out["name"] = node.name;
            if (!node.children.empty()) out["children"] = node.children;
            if (node.mesh >= 0) out["mesh"] = node.mesh;
            if (node.skin >= 0) out["skin"] = node.skin;
            if (!node.weights.empty()) out["weights"] = node.weights;
            if (node.restMatrix) {
                out["matrix"] = floats(&(*node.restMatrix)[0][0], 16);
            } else {
                const Trs& t = node.rest;
                if (t.translation != glm::vec3(0.0f)) out["translation"] = floats(&t.translation[0], 3);
                if (t.rotation != glm::quat(1.0f, 0.0f, 0.0f, 0.0f))
                    out["rotation"] = {t.rotation.x, t.rotation.y, t.rotation.z, t.rotation.w};
                if (t.scale != glm::vec3(1.0f)) out["scale"] = floats(&t.scale[0], 3);
            }
            doc_["nodes"].push_back(out);
        }
    }

    void writeSkins() {
        for (const Skin& skin : scene_.skins) {
            json out = {{"joints", skin.joints}};
            if (!skin.inverseBindMatrices.empty()) {
                std::vector<float> matrices;
                for (const glm::mat4& m : skin.inverseBindMatrices) matrices.insert(matrices.end(), &m[0][0], &m[0][0] + 16);
                out["inverseBindMatrices"] = addAccessor(matrices, kFloat, 16, "MAT4");
            }
            if (skin.skeleton >= 0) out["skeleton"] = skin.skeleton;
            if (!skin.name.empty()) out["name"] = skin.name;
            doc_["skins"].push_back(out);
        }
    }

    void writeAnimations() {
        for (const Animation& animation : scene_.animations) {
            std::vector<char> rotation(animation.samplers.size(), 0);
            for (const AnimationChannel& c : animation.channels)
                if (c.path == AnimationPath::Rotation && c.sampler >= 0 &&
                    static_cast<std::size_t>(c.sampler) < rotation.size())
                    rotation[static_cast<std::size_t>(c.sampler)] = 1;
            json samplers = json::array(), channels = json::array();
            for (std::size_t s = 0; s < animation.samplers.size(); ++s) {
                const AnimationSampler& sampler = animation.samplers[s];
                const char* interpolationName = sampler.interpolation == Interpolation::Linear ? "LINEAR"
                                                : sampler.interpolation == Interpolation::Step ? "STEP" : "CUBICSPLINE";
                if (sampler.weightCount > 0) {  // morph weights: SCALAR, weightCount per key
                    samplers.push_back({{"input", addAccessor(sampler.times, kFloat, 1, "SCALAR", 0, true)},
                                        {"output", addAccessor(sampler.weights, kFloat, 1, "SCALAR")},
                                        {"interpolation", interpolationName}});
                    continue;
                }
                const int width = rotation[s] ? 4 : 3;
                std::vector<float> values;
                for (const glm::vec4& v : sampler.values) values.insert(values.end(), &v[0], &v[0] + width);
                const char* interpolation = sampler.interpolation == Interpolation::Linear ? "LINEAR"
                                            : sampler.interpolation == Interpolation::Step ? "STEP" : "CUBICSPLINE";
                samplers.push_back({{"input", addAccessor(sampler.times, kFloat, 1, "SCALAR", 0, true)},
                                    {"output", addAccessor(values, kFloat, width, width == 4 ? "VEC4" : "VEC3")},
                                    {"interpolation", interpolation}});
            }
            for (const AnimationChannel& c : animation.channels) {
                const char* path = c.path == AnimationPath::Translation ? "translation"
                                   : c.path == AnimationPath::Rotation  ? "rotation"
                                   : c.path == AnimationPath::Weights   ? "weights" : "scale";
                channels.push_back({{"sampler", c.sampler}, {"target", {{"node", c.node}, {"path", path}}}});
            }
            json out = {{"samplers", samplers}, {"channels", channels}};
            if (!animation.name.empty()) out["name"] = animation.name;
            doc_["animations"].push_back(out);
        }
    }

    const Scene& scene_;
    json doc_ = json::object();
    std::vector<std::uint8_t> bin_;
};

}  // namespace

std::string encodeGltf(const Scene& scene, bool binary) {
    Writer writer(scene);
    json doc = writer.build();
    std::vector<std::uint8_t> bin = writer.bin();
    while (bin.size() % 4) bin.push_back(0);
    if (!bin.empty()) doc["buffers"][0]["byteLength"] = bin.size();
    if (!binary) {
        if (!bin.empty()) doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64(bin);
        return doc.dump(1) + "\n";
    }
    std::string text = doc.dump();
    while (text.size() % 4) text += ' ';  // GLB: JSON chunk padded with spaces
    std::string out;
    auto u32 = [&](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    const std::size_t total = 12 + 8 + text.size() + (bin.empty() ? 0 : 8 + bin.size());
    if (total > 0xffffffffu) throw std::invalid_argument("writeGltf: scene too large for GLB");
    u32(0x46546C67);  // "glTF"
    u32(2);
    u32(static_cast<std::uint32_t>(total));
    u32(static_cast<std::uint32_t>(text.size()));
    u32(0x4E4F534A);  // "JSON"
    out += text;
    if (!bin.empty()) {
        u32(static_cast<std::uint32_t>(bin.size()));
        u32(0x004E4942);  // "BIN\0"
        out.append(reinterpret_cast<const char*>(bin.data()), bin.size());
    }
    return out;
}

void writeGltf(const Scene& scene, const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext != ".gltf" && ext != ".glb")
        throw InputError(path.string(), 0, "", "unknown glTF extension '" + ext + "' (use .gltf or .glb)");
    writeFileAtomic(path, encodeGltf(scene, ext == ".glb"));
}

}  // namespace signstim::render
