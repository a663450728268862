// glTF loader: containers, attribute encodings, skins, and clean refusal of broken files.
#include "renderer/gltf_loader.hpp"

#include "common/error.hpp"
#include "gltf_test_files.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>

using namespace signstim;
using namespace signstim::render;
using namespace signstim::render::testing;
namespace fs = std::filesystem;

namespace {

fs::path testDir() { return freshTestDir("gltf_loader"); }

void expectNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

void expectTriangle(const Scene& scene) {
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.meshes[0].primitives.size(), 1u);
    const Primitive& p = scene.meshes[0].primitives[0];
    ASSERT_EQ(p.vertices.size(), 3u);
    EXPECT_EQ(p.indices, (std::vector<std::uint32_t>{0, 1, 2}));
    expectNear(p.vertices[1].position, {1, 0, 0});
    expectNear(p.vertices[2].position, {0, 1, 0});
    for (const Vertex& v : p.vertices) expectNear(v.normal, {0, 0, 1});
    ASSERT_EQ(scene.nodes.size(), 1u);
    EXPECT_EQ(scene.nodes[0].name, "tri");
    EXPECT_EQ(scene.roots, std::vector<int>{0});
}

// Expects loadGltf(path) to throw an InputError whose message names the file and contains
// every one of `words`.
void expectRefused(const fs::path& path, std::initializer_list<const char*> words) {
    try {
        loadGltf(path);
        ADD_FAILURE() << "loaded " << path;
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(path.filename().string()), std::string::npos) << message;
        for (const char* word : words) EXPECT_NE(message.find(word), std::string::npos) << message << "\n  missing: " << word;
    }
}

}  // namespace

TEST(GltfLoader, LoadsExternalBuffer) {
    const fs::path path = triangleGltf().write(testDir(), "tri.gltf", Container::ExternalBuffer);
    expectTriangle(loadGltf(path));
}

TEST(GltfLoader, LoadsEmbeddedDataUriBuffer) {
    const fs::path path = triangleGltf().write(testDir(), "tri.gltf", Container::Embedded);
    expectTriangle(loadGltf(path));
}

TEST(GltfLoader, LoadsGlb) {
    const fs::path path = triangleGltf().write(testDir(), "tri.glb", Container::Glb);
    const Scene scene = loadGltf(path);
    expectTriangle(scene);
    EXPECT_EQ(scene.sourceName, path.string());
}

TEST(GltfLoader, ComputedNormalsAreAreaWeighted) {
    // Two triangles share vertices 0 and 1: a big one in the XY plane (normal +Z, area 2)
    // and a small one in the XZ plane (normal -Y, area 1).
    GltfBuilder b;
    const int positions = b.addFloats({0, 0, 0, 2, 0, 0, 0, 2, 0, 0, 0, -1}, "VEC3", 3);
    const int indices = b.addAccessor(b.addView(std::vector<std::uint8_t>{0, 1, 2, 0, 3, 1}), 5121, 6, "SCALAR");
    b.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", positions}}}, {"indices", indices}}}}}};
    b.doc["nodes"] = {{{"mesh", 0}}};
    const Scene scene = loadGltf(b.write(testDir(), "n.gltf", Container::Embedded));
    const Primitive& p = scene.meshes[0].primitives[0];
    // Shared vertex 0: face cross products (0,0,4) and (0,-2,0) sum to (0,-2,4), so the big
    // face dominates; an unweighted mean would give (0,-1,1).
    expectNear(p.vertices[0].normal, glm::normalize(glm::vec3(0, -2, 4)));
    expectNear(p.vertices[2].normal, {0, 0, 1});
    expectNear(p.vertices[3].normal, {0, -1, 0});
}

TEST(GltfLoader, ReadsNormalizedInterleavedAttributesAndNonIndexedMeshes) {
    GltfBuilder b;
    // Interleaved view: per vertex 3 floats of position + 2 normalized u16 texcoords + pad.
    struct Interleaved {
        float position[3];
        std::uint16_t uv[2];
    };
    std::vector<Interleaved> vertices = {{{0, 0, 0}, {0, 0}}, {{1, 0, 0}, {65535, 0}}, {{0, 1, 0}, {0, 32768}}};
    std::vector<std::uint8_t> raw(vertices.size() * sizeof(Interleaved));
    std::memcpy(raw.data(), vertices.data(), raw.size());
    const int view = b.addView(raw, sizeof(Interleaved));
    const int positions = b.addAccessor(view, 5126, 3, "VEC3");
    const int uvs = b.addAccessor(view, 5123, 3, "VEC2", true, 12);
    b.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}}}}}};
    b.doc["nodes"] = {{{"mesh", 0}}};
    const Scene scene = loadGltf(b.write(testDir(), "i.gltf", Container::Glb));
    const Primitive& p = scene.meshes[0].primitives[0];
    EXPECT_EQ(p.indices, (std::vector<std::uint32_t>{0, 1, 2}));
    expectNear(p.vertices[2].position, {0, 1, 0});
    EXPECT_FLOAT_EQ(p.vertices[1].uv.x, 1.0f);
    EXPECT_NEAR(p.vertices[2].uv.y, 32768.0f / 65535.0f, 1e-6f);
    EXPECT_FALSE(p.skinned);
}

TEST(GltfLoader, AppliesSparseAccessorSubstitutions) {
    GltfBuilder b = triangleGltf();
    // Replace vertex 2 of POSITION with (0, 5, 0) through a sparse accessor.
    const int indexView = b.addView(std::vector<std::uint8_t>{2, 0, 0, 0});
    const int valueView = b.addView(std::vector<float>{0, 5, 0});
    b.doc["accessors"][0]["sparse"] = {{"count", 1},
                                       {"indices", {{"bufferView", indexView}, {"componentType", 5121}}},
                                       {"values", {{"bufferView", valueView}}}};
    const Scene scene = loadGltf(b.write(testDir(), "s.gltf", Container::Embedded));
    expectNear(scene.meshes[0].primitives[0].vertices[2].position, {0, 5, 0});
    expectNear(scene.meshes[0].primitives[0].vertices[1].position, {1, 0, 0});
}

namespace {
// A skinned triangle: joints 0/1 are nodes 1/2; vertex 2 bound to joint 1.
GltfBuilder skinnedGltf(bool inverseBind) {
    GltfBuilder b = triangleGltf();
    const int joints = b.addAccessor(b.addView(std::vector<std::uint8_t>{0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0}), 5121, 3, "VEC4");
    const int weights = b.addAccessor(b.addView(std::vector<std::uint8_t>{255, 0, 0, 0, 255, 0, 0, 0, 128, 128, 0, 0}),
                                      5121, 3, "VEC4", true);
    b.doc["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"] = joints;
    b.doc["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"] = weights;
    b.doc["nodes"] = {{{"mesh", 0}, {"skin", 0}}, {{"name", "hip"}, {"children", {2}}},
                      {{"name", "knee"}, {"translation", {0, 1, 0}}}};
    b.doc["scenes"][0]["nodes"] = {0, 1};
    nlohmann::json skin = {{"joints", {1, 2}}};
    if (inverseBind) {
        std::vector<float> matrices(32, 0.0f);
        for (int m = 0; m < 2; ++m)
            for (int d = 0; d < 4; ++d) matrices[m * 16 + d * 5] = 1.0f;
        matrices[16 + 13] = -1.0f;  // second joint: translate by -1 in Y
        skin["inverseBindMatrices"] = b.addFloats(matrices, "MAT4", 16);
    }
    b.doc["skins"] = nlohmann::json::array({skin});  // not {skin}: clang reads that as a copy of skin
    return b;
}
}  // namespace

TEST(GltfLoader, ReadsSkinWithInverseBindMatrices) {
    const Scene scene = loadGltf(skinnedGltf(true).write(testDir(), "skin.glb", Container::Glb));
    ASSERT_EQ(scene.skins.size(), 1u);
    EXPECT_EQ(scene.skins[0].joints, (std::vector<int>{1, 2}));
    ASSERT_EQ(scene.skins[0].inverseBindMatrices.size(), 2u);
    EXPECT_FLOAT_EQ(scene.skins[0].inverseBindMatrices[1][3][1], -1.0f);
    const Primitive& p = scene.meshes[0].primitives[0];
    EXPECT_TRUE(p.skinned);
    EXPECT_EQ(p.vertices[2].joints, glm::uvec4(1, 0, 0, 0));
    EXPECT_NEAR(p.vertices[2].weights.x, 0.5f, 1e-6f);  // renormalised 128/255 pair
    EXPECT_NEAR(p.vertices[2].weights.x + p.vertices[2].weights.y, 1.0f, 1e-6f);
    EXPECT_EQ(scene.nodes[2].parent, 1);
}

TEST(GltfLoader, SkinWithoutInverseBindMatricesUsesIdentityAndWarns) {
    std::vector<std::string> warnings;
    const Scene scene = loadGltf(skinnedGltf(false).write(testDir(), "skin.gltf", Container::Embedded), &warnings);
    ASSERT_EQ(scene.skins[0].inverseBindMatrices.size(), 2u);
    EXPECT_EQ(scene.skins[0].inverseBindMatrices[0], glm::mat4(1.0f));
    EXPECT_EQ(scene.skins[0].inverseBindMatrices[1], glm::mat4(1.0f));
    bool mentioned = false;
    for (const auto& w : warnings) mentioned |= w.find("inverseBindMatrices") != std::string::npos;
    EXPECT_TRUE(mentioned);
}

TEST(GltfLoader, NodeMatrixIsKeptAndDecomposed) {
    GltfBuilder b = triangleGltf();
    b.doc["nodes"][0]["matrix"] = {2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 1, 2, 3, 1};
    const Scene scene = loadGltf(b.write(testDir(), "m.gltf", Container::Embedded));
    ASSERT_TRUE(scene.nodes[0].restMatrix.has_value());
    expectNear(scene.nodes[0].rest.translation, {1, 2, 3});
    expectNear(scene.nodes[0].rest.scale, {2, 2, 2});
}

// ---- broken input: one test each, InputError naming the file and the problem --------------

TEST(GltfLoaderRefuses, MissingFile) {
    expectRefused(testDir() / "nothing-here.gltf", {"not found"});
}

TEST(GltfLoaderRefuses, Directory) {
    const fs::path dir = testDir() / "folder.gltf";
    fs::create_directories(dir);
    expectRefused(dir, {"directory"});
}

TEST(GltfLoaderRefuses, TruncatedGlb) {
    const fs::path path = triangleGltf().write(testDir(), "cut.glb", Container::Glb);
    fs::resize_file(path, fs::file_size(path) - 10);
    expectRefused(path, {"truncated"});
}

TEST(GltfLoaderRefuses, RandomBytes) {
    const fs::path path = testDir() / "noise.gltf";
    std::ofstream out(path, std::ios::binary);
    std::uint64_t state = 0x9E3779B97F4A7C15ull;  // fixed seed: the same noise every run
    for (int i = 0; i < 4096; ++i) {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        out.put(static_cast<char>(state & 0xff));
    }
    out.close();
    expectRefused(path, {"not a glTF file"});
}

TEST(GltfLoaderRefuses, BufferIndexOutOfRange) {
    GltfBuilder b = triangleGltf();
    b.doc["bufferViews"][1]["buffer"] = 3;
    expectRefused(b.write(testDir(), "b.gltf", Container::Embedded), {"/bufferViews/1/buffer", "out of range"});
}

TEST(GltfLoaderRefuses, BufferViewIndexOutOfRange) {
    GltfBuilder b = triangleGltf();
    b.doc["accessors"][0]["bufferView"] = 7;
    expectRefused(b.write(testDir(), "v.gltf", Container::Embedded), {"/accessors/0/bufferView", "out of range"});
}

TEST(GltfLoaderRefuses, AccessorIndexOutOfRange) {
    GltfBuilder b = triangleGltf();
    b.doc["meshes"][0]["primitives"][0]["indices"] = 42;
    expectRefused(b.write(testDir(), "a.gltf", Container::Embedded),
                  {"/meshes/0/primitives/0/indices", "out of range"});
}

TEST(GltfLoaderRefuses, AccessorReadingPastItsBuffer) {
    GltfBuilder b = triangleGltf();
    b.doc["accessors"][0]["count"] = 1000;
    expectRefused(b.write(testDir(), "p.gltf", Container::Embedded), {"/accessors/0/count", "past the end"});
}

TEST(GltfLoaderRefuses, BufferViewReadingPastItsBuffer) {
    GltfBuilder b = triangleGltf();
    b.doc["bufferViews"][0]["byteOffset"] = 40;
    expectRefused(b.write(testDir(), "bv.glb", Container::Glb), {"/bufferViews/0", "past the end"});
}

TEST(GltfLoaderRefuses, AbsurdByteLength) {
    GltfBuilder b = triangleGltf();
    const fs::path path = b.write(testDir(), "huge.gltf", Container::ExternalBuffer);
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(path));
    doc["buffers"][0]["byteLength"] = 1ull << 50;
    std::ofstream(path) << doc.dump();
    expectRefused(path, {"/buffers/0/byteLength", "exceeds", "huge.gltf.bin"});
}

TEST(GltfLoaderRefuses, AbsurdByteLengthInGlb) {
    GltfBuilder b = triangleGltf();
    const fs::path path = b.write(testDir(), "huge.glb", Container::Glb);
    // Patch the JSON chunk in place: same length, larger number.
    std::string bytes;
    {
        std::ifstream in(path, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    const std::string from = "\"byteLength\":" + std::to_string(b.bin.size()) + "}";
    const std::size_t at = bytes.find(from);
    ASSERT_NE(at, std::string::npos);
    const std::string to = "\"byteLength\":99999999}";
    bytes.replace(at, from.size(), to);
    std::string json = bytes.substr(20);
    std::uint32_t jsonLength;
    std::memcpy(&jsonLength, bytes.data() + 12, 4);
    jsonLength += static_cast<std::uint32_t>(to.size() - from.size());
    std::memcpy(bytes.data() + 12, &jsonLength, 4);
    std::uint32_t total = static_cast<std::uint32_t>(bytes.size());
    std::memcpy(bytes.data() + 8, &total, 4);
    std::ofstream(path, std::ios::binary) << bytes;
    expectRefused(path, {"/buffers/0/byteLength", "exceeds"});
}

TEST(GltfLoaderRefuses, MissingExternalBufferFile) {
    const fs::path path = triangleGltf().write(testDir(), "lost.gltf", Container::ExternalBuffer);
    fs::remove(path.parent_path() / "lost.gltf.bin");
    expectRefused(path, {"/buffers/0/uri", "lost.gltf.bin", "not found"});
}

TEST(GltfLoaderRefuses, IndexPastVertexCount) {
    GltfBuilder b;
    const int positions = b.addFloats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    const int indices = b.addAccessor(b.addView(std::vector<std::uint32_t>{0, 1, 3}), 5125, 3, "SCALAR");
    b.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", positions}}}, {"indices", indices}}}}}};
    expectRefused(b.write(testDir(), "idx.gltf", Container::Embedded), {"/meshes/0/primitives/0/indices", "vertex count"});
}

TEST(GltfLoaderRefuses, JointPastSkinJoints) {
    GltfBuilder b = skinnedGltf(true);
    b.doc["skins"][0]["joints"] = {1};
    b.doc["skins"][0].erase("inverseBindMatrices");
    expectRefused(b.write(testDir(), "j.gltf", Container::Embedded), {"JOINTS_0", "joint 1", "/skins/0"});
}

TEST(GltfLoaderRefuses, NaNPosition) {
    GltfBuilder b;
    const int positions = b.addFloats({0, 0, 0, NAN, 0, 0, 0, 1, 0}, "VEC3", 3);
    b.doc["meshes"] = {{{"primitives", {{{"attributes", {{"POSITION", positions}}}}}}}};
    expectRefused(b.write(testDir(), "nan.gltf", Container::Embedded), {"/accessors/0", "not finite"});
}

TEST(GltfLoaderRefuses, CycleInNodeGraph) {
    GltfBuilder b = triangleGltf();
    b.doc["nodes"] = {{{"children", {1}}}, {{"children", {0}}}};
    b.doc["scenes"][0]["nodes"] = nlohmann::json::array();
    expectRefused(b.write(testDir(), "cycle.gltf", Container::Embedded), {"/nodes/", "cycle"});
}

TEST(GltfLoaderRefuses, NodeWithTwoParents) {
    GltfBuilder b = triangleGltf();
    b.doc["nodes"] = {{{"children", {2}}}, {{"children", {2}}}, {{"mesh", 0}}};
    b.doc["scenes"][0]["nodes"] = {0, 1};
    expectRefused(b.write(testDir(), "dag.gltf", Container::Embedded), {"/nodes/1/children", "already has parent"});
}

// ---- What the Khronos glTF-Validator flags: refused with the JSON pointer of the field ----

TEST(GltfLoaderRefuses, NegativeBufferViewByteOffset) {
    GltfBuilder b = triangleGltf();
    b.doc["bufferViews"][1]["byteOffset"] = -4;
    expectRefused(b.write(testDir(), "offset.gltf", Container::Embedded),
                  {"/bufferViews/1/byteOffset", "non-negative", "-4"});
}

TEST(GltfLoaderRefuses, NegativeAccessorByteOffset) {
    GltfBuilder b = triangleGltf();
    b.doc["accessors"][0]["byteOffset"] = -12;
    expectRefused(b.write(testDir(), "offset.glb", Container::Glb), {"/accessors/0/byteOffset", "non-negative"});
}

TEST(GltfLoaderRefuses, BaseColorFactorOutsideZeroToOne) {
    for (const nlohmann::json& factor : {nlohmann::json{1.0, 0.5, 2.0, 1.0}, nlohmann::json{1.0, 0.5, 0.2},
                                         nlohmann::json{1.0, -0.1, 0.2, 1.0}, nlohmann::json{1.0, "red", 0.2, 1.0}}) {
        GltfBuilder b = triangleGltf();
        b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", factor}}}}};
        b.doc["meshes"][0]["primitives"][0]["material"] = 0;
        expectRefused(b.write(testDir(), "colour.gltf", Container::Embedded),
                      {"/materials/0/pbrMetallicRoughness/baseColorFactor", "4 numbers in [0, 1]"});
    }
}

TEST(GltfLoaderRefuses, TextureSampledWithACoordinateSetThePrimitiveLacks) {
    GltfBuilder b = triangleGltf();  // POSITION only: no TEXCOORD_n at all
    b.doc["images"] = {{{"uri", "data:image/png;base64,iVBORw0KGgo="}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}}}}};
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    expectRefused(b.write(testDir(), "uv.gltf", Container::Embedded),
                  {"/materials/0/pbrMetallicRoughness/baseColorTexture/texCoord", "TEXCOORD_1", "/meshes/0/primitives/0"});
    // texCoord absent means set 0, which the primitive lacks as well.
    b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"].erase("texCoord");
    expectRefused(b.write(testDir(), "uv0.gltf", Container::Embedded), {"baseColorTexture/texCoord", "TEXCOORD_0"});
}

TEST(GltfLoaderRefuses, AnimationWithoutChannels) {
    GltfBuilder b = animatedTriangleGltf({0.0f, 1.0f});
    b.doc["animations"][0]["channels"] = nlohmann::json::array();
    expectRefused(b.write(testDir(), "idle.gltf", Container::Embedded), {"/animations/0/channels", "non-empty"});
}

TEST(GltfLoaderRefuses, NodeWithBothMatrixAndTrs) {
    GltfBuilder b = triangleGltf();
    b.doc["nodes"].push_back({{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}}, {"scale", {2, 2, 2}}});
    b.doc["nodes"][0]["children"] = {1};
    expectRefused(b.write(testDir(), "both.gltf", Container::Embedded), {"/nodes/1'", "matrix", "scale"});
}

TEST(GltfLoaderRefuses, RequiredExtensionItDoesNotImplement) {
    GltfBuilder b = triangleGltf();
    b.doc["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expectRefused(b.write(testDir(), "draco.glb", Container::Glb),
                  {"/extensionsRequired/0", "KHR_draco_mesh_compression", "does not implement"});
    // Used but not required: the file is meant to load without it.
    b.doc.erase("extensionsRequired");
    expectTriangle(loadGltf(b.write(testDir(), "optional.glb", Container::Glb)));
}

TEST(GltfLoaderRefuses, NonFiniteKeyTime) {
    const fs::path path = animatedTriangleGltf({0.0f, INFINITY}).write(testDir(), "forever.gltf", Container::Embedded);
    expectRefused(path, {"/accessors/2", "/animations/0/samplers/0/input", "not finite"});
}

TEST(GltfLoaderRefuses, NonFiniteKeyValue) {
    GltfBuilder b = animatedTriangleGltf({0.0f, 1.0f});
    float nan = NAN;
    std::memcpy(b.bin.data() + b.doc["bufferViews"][3]["byteOffset"].get<std::size_t>() + 4, &nan, 4);
    expectRefused(b.write(testDir(), "nan.gltf", Container::Embedded),
                  {"/accessors/3", "/animations/0/samplers/0/output", "not finite"});
}

TEST(GltfLoader, AnimationNamesTheAccessorOfItsLastKey) {
    // A key at 1e9 s is a valid file; whoever samples it decides whether that is too long
    // and names this accessor when refusing (render-gltf: more than one hour).
    const Scene scene = loadGltf(animatedTriangleGltf({0.0f, 1e9f}).write(testDir(), "long.gltf", Container::Embedded));
    ASSERT_EQ(scene.animations.size(), 1u);
    EXPECT_FLOAT_EQ(scene.animations[0].durationSeconds, 1e9f);
    EXPECT_EQ(scene.animations[0].durationSource, "/accessors/2");
}

// ---- URIs stay in the model's folder unless the user allows another ----

namespace {

// triangleGltf() with its buffer in `dir`/`binName` (any relative or absolute path) and the
// glTF in `dir`/model/model.gltf naming it by `uri`.
fs::path modelWithBufferAt(const fs::path& dir, const fs::path& binFile, const std::string& uri) {
    GltfBuilder b = triangleGltf();
    const fs::path model = b.write(dir / "model", "model.gltf", Container::ExternalBuffer);
    fs::create_directories(binFile.parent_path());
    fs::rename(dir / "model" / "model.gltf.bin", binFile);
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(model));
    doc["buffers"][0]["uri"] = uri;
    std::ofstream(model) << doc.dump();
    return model;
}

}  // namespace

TEST(GltfLoaderRefuses, BufferUriLeavingTheModelsFolder) {
    const fs::path dir = testDir();
    const fs::path model = modelWithBufferAt(dir, dir / "elsewhere" / "data.bin", "../elsewhere/data.bin");
    expectRefused(model, {"/buffers/0/uri", "../elsewhere/data.bin", "leads out of the model's folder"});
    // The same file, allowed by the user.
    GltfLoadOptions options;
    options.allowedDirectories = {dir / "elsewhere"};
    options.allowFlag = "--allow-dir";
    expectTriangle(loadGltf(model, options));
    // Allowing another folder does not allow this one.
    options.allowedDirectories = {dir / "model"};
    EXPECT_THROW(loadGltf(model, options), InputError);
}

TEST(GltfLoaderRefuses, ImageUriReadingSystemFiles) {
    GltfBuilder b = triangleGltf();
    b.doc["images"] = {{{"uri", "../../../../../../../../etc/passwd"}}};
    GltfLoadOptions options;
    options.allowFlag = "--allow-dir";
    const fs::path path = b.write(testDir(), "thief.gltf", Container::Embedded);
    try {
        loadGltf(path, options);
        ADD_FAILURE() << "loaded " << path;
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("/images/0/uri"), std::string::npos) << message;
        EXPECT_NE(message.find("leads out of"), std::string::npos) << message;
        EXPECT_NE(message.find("--allow-dir"), std::string::npos) << message;  // says how to allow one
    }
    // Percent-encoded dots are decoded (as tinygltf does) before the check.
    b.doc["images"][0]["uri"] = "%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/%2e%2e/etc/passwd";
    expectRefused(b.write(testDir(), "encoded.gltf", Container::Embedded), {"/images/0/uri", "leads out of"});
    b.doc["images"][0]["uri"] = "/etc/passwd";
    expectRefused(b.write(testDir(), "absolute.gltf", Container::Embedded), {"/images/0/uri", "absolute path"});
}

TEST(GltfLoaderRefuses, SymbolicLinkOutOfTheModelsFolder) {
    const fs::path dir = testDir();
    const fs::path model = modelWithBufferAt(dir, dir / "outside" / "data.bin", "link.bin");
    fs::create_symlink(dir / "outside" / "data.bin", dir / "model" / "link.bin");
    expectRefused(model, {"/buffers/0/uri", "leads out of"});
}

TEST(GltfLoader, RelativeUriInsideTheModelsFolderLoads) {
    const fs::path dir = testDir();
    expectTriangle(loadGltf(modelWithBufferAt(dir, dir / "model" / "data" / "tri.bin", "data/../data/tri.bin")));
}
