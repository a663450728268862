// glTF conversion: a validated model (gltf_validate.hpp) into the CPU Scene.
#include "renderer/gltf_loader.hpp"

#include "renderer/gltf_morph.hpp"

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace signstim::render {
namespace fs = std::filesystem;

namespace {
using gltf_detail::at;
using gltf_detail::componentCount;
using gltf_detail::typeName;

class Converter {
public:
    Converter(ValidatedGltf gltf, std::vector<std::string>* warnings)
        : gltf_(std::move(gltf)), model_(gltf_.model()), file_(gltf_.fileName()), warnings_(warnings) {}

    // Some checks below are validation in kind, on the tinygltf model rather than on converted
    // data: enum values (wrap modes, filters, alpha modes, primitive modes, interpolation,
    // animation paths), finite factors and transforms, attribute counts against POSITION, an
    // animation output's type and count. They stay here, in conversion order, because that
    // order decides which error a file with several gets (an image that does not decode is
    // reported before a bad wrap mode): moved into the validator, they would be reported
    // first. Checks on the values read from accessors (indices past the vertex count,
    // negative weights, key times, zero rotation keys) and those marked "needs converted
    // data" belong here. Accessor data is read through ValidatedGltf::readAccessor, which
    // checks the accessor (types, ranges, sparse part) and the values for NaN/Inf.
    Scene convert() {
        Scene scene;
        scene.sourceName = file_;
        convertImages(scene);
        convertSamplersAndTextures(scene);
        convertMaterials(scene);
        convertNodes(scene);
        convertMeshes(scene);
        gltf_morph::convertNodeWeights(gltf_, scene);
        convertSkins(scene);
        checkSkinnedJoints(scene);
        convertAnimations(scene);
        return scene;
    }

private:
    [[noreturn]] void fail(const std::string& field, const std::string& message) const { gltf_.fail(field, message); }
    void warn(const std::string& message) {
        if (warnings_) warnings_->push_back(file_ + ": " + message);
    }

    // ---- scene conversion -------------------------------------------------------------------
    void convertImages(Scene& scene) {
        for (std::size_t i = 0; i < model_.images.size(); ++i) {
            tinygltf::Image& image = model_.images[i];
            const std::string f = at("images", i);
            if (image.bufferView >= 0 && image.image.empty()) {
                const tinygltf::BufferView& view = model_.bufferViews[static_cast<std::size_t>(image.bufferView)];
                if (view.byteLength > static_cast<std::size_t>(std::numeric_limits<int>::max()))
                    fail(f + "/bufferView", "image data too large");
                std::string err, warnText;
                if (!tinygltf::LoadImageData(&image, static_cast<int>(i), &err, &warnText, 0, 0,
                                             gltf_.viewData(image.bufferView), static_cast<int>(view.byteLength),
                                             nullptr))
                    fail(f, "cannot decode image: " + err);
            }
            if (image.image.empty() || image.width < 1 || image.height < 1)
                fail(f, "image could not be decoded (PNG or JPEG expected)");
            ImageData out;
            out.name = image.name;
            out.width = static_cast<std::uint32_t>(image.width);
            out.height = static_cast<std::uint32_t>(image.height);
            const std::size_t pixels = static_cast<std::size_t>(out.width) * out.height;
            const int channels = image.component;
            const int bytesPerChannel = image.bits == 16 ? 2 : 1;
            if (channels < 1 || channels > 4 ||
                image.image.size() < pixels * static_cast<std::size_t>(channels * bytesPerChannel))
                fail(f, "decoded image has an unexpected layout");
            out.rgba.resize(pixels * 4);
            for (std::size_t p = 0; p < pixels; ++p) {
                std::uint8_t c[4] = {0, 0, 0, 255};
                for (int k = 0; k < channels; ++k) {
                    const std::size_t at = (p * channels + k) * bytesPerChannel;
                    // 16-bit: keep the high byte (native little-endian from stb).
                    c[k] = bytesPerChannel == 2 ? image.image[at + 1] : image.image[at];
                }
                if (channels == 1 || channels == 2) {  // grey (+ alpha)
                    const std::uint8_t alpha = channels == 2 ? c[1] : 255;
                    c[1] = c[2] = c[0];
                    c[3] = alpha;
                }
                std::memcpy(&out.rgba[p * 4], c, 4);
            }
            scene.images.push_back(std::move(out));
        }
    }

    void convertSamplersAndTextures(Scene& scene) {
        for (std::size_t i = 0; i < model_.textures.size(); ++i) {
            const tinygltf::Texture& texture = model_.textures[i];
            Texture out;
            out.image = texture.source;
            if (out.image < 0) warn(at("textures", i) + " has no source image (extension?); it is ignored");
            if (texture.sampler >= 0) {
                const tinygltf::Sampler& s = model_.samplers[static_cast<std::size_t>(texture.sampler)];
                const std::string f = at("samplers", static_cast<std::size_t>(texture.sampler));
                auto wrap = [&](int mode, const char* key) {
                    switch (mode) {
                        case TINYGLTF_TEXTURE_WRAP_REPEAT: return Wrap::Repeat;
                        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return Wrap::ClampToEdge;
                        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return Wrap::MirroredRepeat;
                        default: fail(f + "/" + key, "unknown wrap mode " + std::to_string(mode));
                    }
                };
                out.wrapS = wrap(s.wrapS, "wrapS");
                out.wrapT = wrap(s.wrapT, "wrapT");
                if (s.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST) out.magFilter = Filter::Nearest;
                else if (s.magFilter != -1 && s.magFilter != TINYGLTF_TEXTURE_FILTER_LINEAR)
                    fail(f + "/magFilter", "unknown filter " + std::to_string(s.magFilter));
                switch (s.minFilter) {
                    case -1: break;
                    case TINYGLTF_TEXTURE_FILTER_NEAREST: out.minFilter = Filter::Nearest; out.mipmaps = false; break;
                    case TINYGLTF_TEXTURE_FILTER_LINEAR: out.mipmaps = false; break;
                    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
                    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: out.minFilter = Filter::Nearest; break;
                    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
                    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR: break;
                    default: fail(f + "/minFilter", "unknown filter " + std::to_string(s.minFilter));
                }
            }
            scene.textures.push_back(out);
        }
    }

    static bool finite(const std::vector<double>& v) {
        return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
    }

    void convertMaterials(Scene& scene) {
        for (std::size_t i = 0; i < model_.materials.size(); ++i) {
            const tinygltf::Material& m = model_.materials[i];
            const std::string f = at("materials", i);
            Material out;
            out.name = m.name;
            const auto& pbr = m.pbrMetallicRoughness;
            if (pbr.baseColorFactor.size() != 4 || !finite(pbr.baseColorFactor))
                fail(f + "/pbrMetallicRoughness/baseColorFactor", "must be 4 finite numbers");
            out.baseColorFactor = glm::vec4(pbr.baseColorFactor[0], pbr.baseColorFactor[1],
                                            pbr.baseColorFactor[2], pbr.baseColorFactor[3]);
            auto unit = [&](double v, const std::string& field) {
                if (!(v >= 0.0 && v <= 1.0)) fail(field, "must be in [0, 1]");
                return static_cast<float>(v);
            };
            out.metallicFactor = unit(pbr.metallicFactor, f + "/pbrMetallicRoughness/metallicFactor");
            out.roughnessFactor = unit(pbr.roughnessFactor, f + "/pbrMetallicRoughness/roughnessFactor");
            out.baseColorTexture = pbr.baseColorTexture.index;
            out.metallicRoughnessTexture = pbr.metallicRoughnessTexture.index;
            if (pbr.baseColorTexture.texCoord != 0 || pbr.metallicRoughnessTexture.texCoord != 0)
                warn(f + " uses TEXCOORD_1+; only TEXCOORD_0 is supported");
            if (m.emissiveFactor.size() != 3 || !finite(m.emissiveFactor))
                fail(f + "/emissiveFactor", "must be 3 finite numbers");
            out.emissiveFactor = glm::vec3(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]);
            if (m.alphaMode == "OPAQUE" || m.alphaMode.empty()) out.alphaMode = AlphaMode::Opaque;
            else if (m.alphaMode == "MASK") out.alphaMode = AlphaMode::Mask;
            else if (m.alphaMode == "BLEND") out.alphaMode = AlphaMode::Blend;
            else fail(f + "/alphaMode", "must be OPAQUE, MASK or BLEND, got \"" + m.alphaMode + "\"");
            if (!(m.alphaCutoff >= 0.0) || !std::isfinite(m.alphaCutoff))
                fail(f + "/alphaCutoff", "must be a non-negative number");
            out.alphaCutoff = static_cast<float>(m.alphaCutoff);
            out.doubleSided = m.doubleSided;
            scene.materials.push_back(out);
        }
    }

    void convertNodes(Scene& scene) {
        const std::size_t count = model_.nodes.size();
        scene.nodes.resize(count);
        for (std::size_t i = 0; i < count; ++i) {
            const tinygltf::Node& n = model_.nodes[i];
            const std::string f = at("nodes", i);
            Node& out = scene.nodes[i];
            out.name = n.name;
            out.mesh = n.mesh;
            out.skin = n.skin;
            out.children = n.children;
            auto vec = [&](const std::vector<double>& v, std::size_t size, const char* key) {
                if (v.empty()) return false;
                if (v.size() != size || !finite(v))
                    fail(f + "/" + key, "must be " + std::to_string(size) + " finite numbers");
                return true;
            };
            if (vec(n.translation, 3, "translation"))
                out.rest.translation = glm::vec3(n.translation[0], n.translation[1], n.translation[2]);
            if (vec(n.scale, 3, "scale")) out.rest.scale = glm::vec3(n.scale[0], n.scale[1], n.scale[2]);
            if (vec(n.rotation, 4, "rotation")) {
                const glm::quat q(static_cast<float>(n.rotation[3]), static_cast<float>(n.rotation[0]),
                                  static_cast<float>(n.rotation[1]), static_cast<float>(n.rotation[2]));
                if (glm::length(q) < 1e-6f) fail(f + "/rotation", "quaternion has zero length");
                out.rest.rotation = glm::normalize(q);
            }
            if (vec(n.matrix, 16, "matrix")) {
                glm::mat4 m;
                for (int c = 0; c < 4; ++c)
                    for (int r = 0; r < 4; ++r) m[c][r] = static_cast<float>(n.matrix[static_cast<std::size_t>(c * 4 + r)]);
                out.restMatrix = m;
                out.rest = decompose(m);
            }
        }
        // One parent per node, no cycles (needs converted data: the parent links set here).
        for (std::size_t i = 0; i < count; ++i)
            for (int child : scene.nodes[i].children) {
                Node& c = scene.nodes[static_cast<std::size_t>(child)];
                if (c.parent >= 0 || child == static_cast<int>(i))
                    fail(at("nodes", i) + "/children",
                         "/nodes/" + std::to_string(child) + " " +
                             (child == static_cast<int>(i) ? std::string("is its own child")
                                                           : "already has parent /nodes/" + std::to_string(c.parent)) +
                             " (the node graph must be a forest)");
                c.parent = static_cast<int>(i);
            }
        std::vector<char> reached(count, 0);
        std::vector<int> stack;
        for (std::size_t i = 0; i < count; ++i) {
            if (scene.nodes[i].parent >= 0) continue;
            stack.push_back(static_cast<int>(i));
            while (!stack.empty()) {
                const int n = stack.back();
                stack.pop_back();
                reached[static_cast<std::size_t>(n)] = 1;
                for (int c : scene.nodes[static_cast<std::size_t>(n)].children) stack.push_back(c);
            }
        }
        for (std::size_t i = 0; i < count; ++i)
            if (!reached[i]) fail(at("nodes", i) + "/children", "node is part of a cycle in the node graph");

        if (!model_.scenes.empty()) {
            const std::size_t sceneIndex = model_.defaultScene >= 0 ? static_cast<std::size_t>(model_.defaultScene) : 0;
            scene.roots = model_.scenes[sceneIndex].nodes;
            for (int r : scene.roots)
                if (scene.nodes[static_cast<std::size_t>(r)].parent >= 0)
                    fail(at("scenes", sceneIndex) + "/nodes", "/nodes/" + std::to_string(r) + " is not a root node");
        } else {
            for (std::size_t i = 0; i < count; ++i)
                if (scene.nodes[i].parent < 0) scene.roots.push_back(static_cast<int>(i));
        }
    }

    static Trs decompose(const glm::mat4& m) {
        Trs trs;
        trs.translation = glm::vec3(m[3]);
        glm::vec3 columns[3] = {glm::vec3(m[0]), glm::vec3(m[1]), glm::vec3(m[2])};
        trs.scale = glm::vec3(glm::length(columns[0]), glm::length(columns[1]), glm::length(columns[2]));
        if (glm::determinant(glm::mat3(m)) < 0.0f) trs.scale.x = -trs.scale.x;
        glm::mat3 rotation(1.0f);
        for (int c = 0; c < 3; ++c)
            if (trs.scale[c] != 0.0f) rotation[c] = columns[c] / trs.scale[c];
        trs.rotation = glm::normalize(glm::quat_cast(rotation));
        return trs;
    }

    void convertMeshes(Scene& scene) {
        using T = int;
        constexpr T kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT, kU8 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                    kU16 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, kU32 = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                    kI8 = TINYGLTF_COMPONENT_TYPE_BYTE, kI16 = TINYGLTF_COMPONENT_TYPE_SHORT;
        for (std::size_t m = 0; m < model_.meshes.size(); ++m) {
            Mesh mesh;
            mesh.name = model_.meshes[m].name;
            gltf_morph::convertMeshMorphs(gltf_, m, mesh);
            for (std::size_t p = 0; p < model_.meshes[m].primitives.size(); ++p) {
                const tinygltf::Primitive& prim = model_.meshes[m].primitives[p];
                const std::string f = at(at("meshes", m) + "/primitives", p);
                if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
                    prim.mode != TINYGLTF_MODE_TRIANGLE_FAN) {
                    if (prim.mode < 0 || prim.mode > 6) fail(f + "/mode", "unknown primitive mode " + std::to_string(prim.mode));
                    warn(f + ": points/lines primitive skipped (only triangles are drawn)");
                    continue;
                }
                const auto attribute = [&](const char* name) {
                    const auto it = prim.attributes.find(name);
                    return it == prim.attributes.end() ? -1 : it->second;
                };
                const int positionIndex = attribute("POSITION");
                if (positionIndex < 0) fail(f + "/attributes/POSITION", "is required");
                const std::vector<double> positions =
                    gltf_.readAccessor(positionIndex, {TINYGLTF_TYPE_VEC3}, {}, f + "/attributes/POSITION");
                const std::size_t vertexCount = positions.size() / 3;
                Primitive out;
                out.material = prim.material;
                out.vertices.resize(vertexCount);
                for (std::size_t v = 0; v < vertexCount; ++v)
                    out.vertices[v].position = glm::vec3(positions[v * 3], positions[v * 3 + 1], positions[v * 3 + 2]);

                auto readAttribute = [&](const char* name, int type, std::initializer_list<int> componentTypes) {
                    const int index = attribute(name);
                    if (index < 0) return std::vector<double>{};
                    std::vector<double> values = gltf_.readAccessor(index, {type}, componentTypes,
                                                                    f + "/attributes/" + name);
                    const std::size_t count = model_.accessors[static_cast<std::size_t>(index)].count;
                    if (count != vertexCount)
                        fail(f + "/attributes/" + name, "has " + std::to_string(count) +
                                                            " elements but POSITION has " + std::to_string(vertexCount));
                    return values;
                };
                const std::vector<double> normals = readAttribute("NORMAL", TINYGLTF_TYPE_VEC3, {kFloat});
                const std::vector<double> uvs = readAttribute("TEXCOORD_0", TINYGLTF_TYPE_VEC2, {kFloat, kU8, kU16});
                const std::vector<double> joints = readAttribute("JOINTS_0", TINYGLTF_TYPE_VEC4, {kU8, kU16});
                const std::vector<double> weights =
                    readAttribute("WEIGHTS_0", TINYGLTF_TYPE_VEC4, {kFloat, kU8, kU16});
                (void)kI8;
                (void)kI16;
                for (std::size_t v = 0; v < vertexCount && !uvs.empty(); ++v)
                    out.vertices[v].uv = glm::vec2(uvs[v * 2], uvs[v * 2 + 1]);
                if (joints.empty() != weights.empty())
                    warn(f + ": JOINTS_0 without WEIGHTS_0 (or the reverse); drawn unskinned");
                if (!joints.empty() && !weights.empty()) {
                    out.skinned = true;
                    bool zeroWeights = false;
                    for (std::size_t v = 0; v < vertexCount; ++v) {
                        Vertex& vertex = out.vertices[v];
                        glm::vec4 w(weights[v * 4], weights[v * 4 + 1], weights[v * 4 + 2], weights[v * 4 + 3]);
                        if (glm::any(glm::lessThan(w, glm::vec4(0.0f))))
                            fail(f + "/attributes/WEIGHTS_0", "vertex " + std::to_string(v) + " has a negative weight");
                        const float sum = w.x + w.y + w.z + w.w;
                        if (sum <= 1e-6f) {
                            zeroWeights = true;
                            w = glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
                        } else {
                            w /= sum;
                        }
                        vertex.weights = w;
                        for (int k = 0; k < 4; ++k)
                            vertex.joints[k] = static_cast<std::uint32_t>(joints[v * 4 + static_cast<std::size_t>(k)]);
                    }
                    if (zeroWeights) warn(f + ": vertices with all-zero weights bound fully to their first joint");
                }

                if (prim.indices >= 0) {
                    const std::vector<double> indices =
                        gltf_.readAccessor(prim.indices, {TINYGLTF_TYPE_SCALAR}, {kU8, kU16, kU32}, f + "/indices");
                    out.indices.reserve(indices.size());
                    for (std::size_t i = 0; i < indices.size(); ++i) {
                        if (indices[i] >= static_cast<double>(vertexCount))
                            fail(f + "/indices", "index " + std::to_string(static_cast<std::uint64_t>(indices[i])) +
                                                     " (element " + std::to_string(i) + ") is past the vertex count " +
                                                     std::to_string(vertexCount));
                        out.indices.push_back(static_cast<std::uint32_t>(indices[i]));
                    }
                } else {
                    out.indices.resize(vertexCount);
                    for (std::size_t i = 0; i < vertexCount; ++i) out.indices[i] = static_cast<std::uint32_t>(i);
                }
                out.indices = toTriangleList(std::move(out.indices), prim.mode, f);
                if (normals.empty()) {
                    computeSmoothNormals(out);
                } else {
                    for (std::size_t v = 0; v < vertexCount; ++v) {
                        const glm::vec3 n(normals[v * 3], normals[v * 3 + 1], normals[v * 3 + 2]);
                        const float length = glm::length(n);
                        out.vertices[v].normal = length > 1e-12f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
                    }
                }
                gltf_morph::convertPrimitiveTargets(gltf_, m, p, out, warnings_);
                mesh.primitives.push_back(std::move(out));
            }
            scene.meshes.push_back(std::move(mesh));
        }
    }

    std::vector<std::uint32_t> toTriangleList(std::vector<std::uint32_t> indices, int mode, const std::string& f) {
        if (mode == TINYGLTF_MODE_TRIANGLES) {
            if (indices.size() % 3 != 0)
                fail(f, std::to_string(indices.size()) + " indices/vertices is not a multiple of 3 (triangle list)");
            return indices;
        }
        std::vector<std::uint32_t> list;
        if (indices.size() < 3) return list;
        for (std::size_t i = 2; i < indices.size(); ++i) {
            if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
                // Alternate winding so every triangle keeps the strip's orientation.
                if (i % 2 == 0) list.insert(list.end(), {indices[i - 2], indices[i - 1], indices[i]});
                else list.insert(list.end(), {indices[i - 1], indices[i - 2], indices[i]});
            } else {
                list.insert(list.end(), {indices[0], indices[i - 1], indices[i]});
            }
        }
        return list;
    }

    static void computeSmoothNormals(Primitive& primitive) {
        std::vector<glm::vec3> sums(primitive.vertices.size(), glm::vec3(0.0f));
        for (std::size_t t = 0; t + 2 < primitive.indices.size(); t += 3) {
            const std::uint32_t a = primitive.indices[t], b = primitive.indices[t + 1], c = primitive.indices[t + 2];
            const glm::vec3& pa = primitive.vertices[a].position;
            // Unnormalised cross product: its length is twice the area, so big faces weigh more.
            const glm::vec3 n = glm::cross(primitive.vertices[b].position - pa, primitive.vertices[c].position - pa);
            sums[a] += n;
            sums[b] += n;
            sums[c] += n;
        }
        for (std::size_t v = 0; v < sums.size(); ++v) {
            const float length = glm::length(sums[v]);
            primitive.vertices[v].normal = length > 1e-20f ? sums[v] / length : glm::vec3(0.0f, 0.0f, 1.0f);
        }
    }

    void convertSkins(Scene& scene) {
        for (std::size_t i = 0; i < model_.skins.size(); ++i) {
            const tinygltf::Skin& s = model_.skins[i];
            const std::string f = at("skins", i);
            Skin out;
            out.name = s.name;
            out.joints = s.joints;
            out.skeleton = s.skeleton;
            if (s.inverseBindMatrices >= 0) {
                const std::vector<double> values =
                    gltf_.readAccessor(s.inverseBindMatrices, {TINYGLTF_TYPE_MAT4}, {TINYGLTF_COMPONENT_TYPE_FLOAT},
                                       f + "/inverseBindMatrices");
                const std::size_t count = values.size() / 16;
                if (count < out.joints.size())
                    fail(f + "/inverseBindMatrices", "has " + std::to_string(count) + " matrices for " +
                                                         std::to_string(out.joints.size()) + " joints");
                for (std::size_t j = 0; j < out.joints.size(); ++j) {
                    glm::mat4 m;
                    for (int c = 0; c < 4; ++c)
                        for (int r = 0; r < 4; ++r) m[c][r] = static_cast<float>(values[j * 16 + static_cast<std::size_t>(c * 4 + r)]);
                    out.inverseBindMatrices.push_back(m);
                }
            } else {
                out.inverseBindMatrices.assign(out.joints.size(), glm::mat4(1.0f));
            }
            scene.skins.push_back(std::move(out));
        }
    }

    // Joint indices against the joints of the skin each mesh is drawn with (needs converted
    // data: the JOINTS_0 values read, and which node pairs which mesh with which skin).
    void checkSkinnedJoints(Scene& scene) {
        for (std::size_t n = 0; n < scene.nodes.size(); ++n) {
            const Node& node = scene.nodes[n];
            if (node.mesh < 0 || node.skin < 0) continue;
            const std::size_t jointCount = scene.skins[static_cast<std::size_t>(node.skin)].joints.size();
            Mesh& mesh = scene.meshes[static_cast<std::size_t>(node.mesh)];
            for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
                Primitive& prim = mesh.primitives[p];
                if (!prim.skinned) continue;
                for (std::size_t v = 0; v < prim.vertices.size(); ++v)
                    for (int k = 0; k < 4; ++k) {
                        std::uint32_t& joint = prim.vertices[v].joints[k];
                        if (joint < jointCount) continue;
                        if (prim.vertices[v].weights[k] == 0.0f) {
                            joint = 0;  // unused influence; keep it harmless
                            continue;
                        }
                        fail(at(at("meshes", static_cast<std::size_t>(node.mesh)) + "/primitives", p) +
                                 "/attributes/JOINTS_0",
                             "vertex " + std::to_string(v) + " uses joint " + std::to_string(joint) + " but /skins/" +
                                 std::to_string(node.skin) + " (of /nodes/" + std::to_string(n) + ") has " +
                                 std::to_string(jointCount) + " joints");
                    }
            }
        }
    }

    void convertAnimations(Scene& scene) {
        for (std::size_t a = 0; a < model_.animations.size(); ++a) {
            const tinygltf::Animation& animation = model_.animations[a];
            const std::string f = at("animations", a);
            Animation out;
            out.name = animation.name;
            std::vector<int> samplerOutputType(animation.samplers.size(), 0);
            for (std::size_t s = 0; s < animation.samplers.size(); ++s) {
                const tinygltf::AnimationSampler& sampler = animation.samplers[s];
                const std::string sf = at(f + "/samplers", s);
                AnimationSampler so;
                if (sampler.interpolation == "LINEAR" || sampler.interpolation.empty()) so.interpolation = Interpolation::Linear;
                else if (sampler.interpolation == "STEP") so.interpolation = Interpolation::Step;
                else if (sampler.interpolation == "CUBICSPLINE") so.interpolation = Interpolation::CubicSpline;
                else fail(sf + "/interpolation", "must be LINEAR, STEP or CUBICSPLINE, got \"" + sampler.interpolation + "\"");
                const std::vector<double> times = gltf_.readAccessor(sampler.input, {TINYGLTF_TYPE_SCALAR},
                                                                     {TINYGLTF_COMPONENT_TYPE_FLOAT}, sf + "/input");
                for (std::size_t k = 0; k < times.size(); ++k) {
                    if (times[k] < 0.0) fail(sf + "/input", "key time " + std::to_string(times[k]) + " is negative");
                    if (k > 0 && !(times[k] > times[k - 1]))
                        fail(sf + "/input", "key times must increase strictly (key " + std::to_string(k) + ")");
                    so.times.push_back(static_cast<float>(times[k]));
                }
                const tinygltf::Accessor& output = model_.accessors[static_cast<std::size_t>(sampler.output)];
                const int width = componentCount(output.type);
                if (output.type != TINYGLTF_TYPE_VEC3 && output.type != TINYGLTF_TYPE_VEC4 &&
                    output.type != TINYGLTF_TYPE_SCALAR)
                    fail(at("accessors", static_cast<std::size_t>(sampler.output)) + "/type",
                         "animation output must be VEC3, VEC4 (or SCALAR for weights)");
                samplerOutputType[s] = output.type;
                const std::vector<double> values =
                    gltf_.readAccessor(sampler.output, {TINYGLTF_TYPE_SCALAR, TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4},
                                       {}, sf + "/output");
                const std::size_t expected = times.size() * (so.interpolation == Interpolation::CubicSpline ? 3 : 1);
                if (output.type != TINYGLTF_TYPE_SCALAR && output.count != expected)
                    fail(sf + "/output", "has " + std::to_string(output.count) + " values for " +
                                             std::to_string(times.size()) + " key times (expected " +
                                             std::to_string(expected) + ")");
                for (std::size_t v = 0; output.type != TINYGLTF_TYPE_SCALAR && v < output.count; ++v) {
                    glm::vec4 value(0.0f);
                    for (int c = 0; c < width; ++c) value[c] = static_cast<float>(values[v * width + static_cast<std::size_t>(c)]);
                    so.values.push_back(value);
                }
                if (output.type == TINYGLTF_TYPE_SCALAR)  // morph weights; checked per channel
                    so.weights.assign(values.begin(), values.end());
                if (!so.times.empty() && so.times.back() >= out.durationSeconds) {
                    out.durationSeconds = so.times.back();
                    out.durationSource = at("accessors", static_cast<std::size_t>(sampler.input));
                }
                out.samplers.push_back(std::move(so));
            }
            std::vector<char> isRotation(animation.samplers.size(), 0);
            for (std::size_t c = 0; c < animation.channels.size(); ++c) {
                const tinygltf::AnimationChannel& channel = animation.channels[c];
                const std::string cf = at(f + "/channels", c);
                if (channel.target_node < 0) continue;  // extension-targeted channel
                AnimationChannel co;
                co.node = channel.target_node;
                co.sampler = channel.sampler;
                int needed = TINYGLTF_TYPE_VEC3;
                if (channel.target_path == "translation") co.path = AnimationPath::Translation;
                else if (channel.target_path == "scale") co.path = AnimationPath::Scale;
                else if (channel.target_path == "rotation") {
                    co.path = AnimationPath::Rotation;
                    needed = TINYGLTF_TYPE_VEC4;
                } else if (channel.target_path == "weights") {
                    co.path = AnimationPath::Weights;
                    needed = TINYGLTF_TYPE_SCALAR;
                } else {
                    fail(cf + "/target/path", "unknown path \"" + channel.target_path + "\"");
                }
                if (samplerOutputType[static_cast<std::size_t>(co.sampler)] != needed)
                    fail(cf + "/sampler", "output of " + at(f + "/samplers", static_cast<std::size_t>(co.sampler)) +
                                              " is not " + typeName(needed) + " as " + channel.target_path + " needs");
                // (needs converted data: the node's restMatrix)
                if (scene.nodes[static_cast<std::size_t>(co.node)].restMatrix)
                    fail(cf + "/target/node", "animated nodes must not use `matrix` (glTF 2.0 §3.7.3.2)");
                if (co.path == AnimationPath::Weights)
                    gltf_morph::convertWeightsChannel(gltf_, scene, a, c, out.samplers[static_cast<std::size_t>(co.sampler)]);
                if (co.path == AnimationPath::Rotation) isRotation[static_cast<std::size_t>(co.sampler)] = 1;
                out.channels.push_back(co);
            }
            // Rotation keys are unit quaternions; normalise the values (not cubic tangents).
            for (std::size_t s = 0; s < out.samplers.size(); ++s) {
                if (!isRotation[s]) continue;
                AnimationSampler& sampler = out.samplers[s];
                const bool cubic = sampler.interpolation == Interpolation::CubicSpline;
                for (std::size_t v = cubic ? 1 : 0; v < sampler.values.size(); v += cubic ? 3 : 1) {
                    const float length = glm::length(sampler.values[v]);
                    if (length < 1e-6f)
                        fail(at(f + "/samplers", s) + "/output", "rotation key " + std::to_string(cubic ? v / 3 : v) +
                                                                     " is a zero quaternion");
                    sampler.values[v] /= length;
                }
            }
            scene.animations.push_back(std::move(out));
        }
    }

    ValidatedGltf gltf_;
    tinygltf::Model& model_;
    std::string file_;
    std::vector<std::string>* warnings_;
};

}  // namespace

Scene convertGltf(ValidatedGltf gltf, std::vector<std::string>* warnings) {
    return Converter(std::move(gltf), warnings).convert();
}

Scene loadGltf(const fs::path& path, std::vector<std::string>* warnings) {
    return convertGltf(validateGltf(path, GltfLoadOptions{}, warnings), warnings);
}

Scene loadGltf(const fs::path& path, const GltfLoadOptions& options, std::vector<std::string>* warnings) {
    return convertGltf(validateGltf(path, options, warnings), warnings);
}

Scene loadGltfBytes(std::string bytes, const std::string& fileName, const fs::path& baseDirectory,
                    const GltfLoadOptions& options, std::vector<std::string>* warnings) {
    return convertGltf(validateGltfBytes(std::move(bytes), fileName, baseDirectory, options, warnings), warnings);
}

}  // namespace signstim::render
