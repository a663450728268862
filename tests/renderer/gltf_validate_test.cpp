// glTF validation from memory (validateGltfBytes, loadGltfBytes): what a fuzz target calls.
// The bytes behave as the file they came from: same model, same errors, URIs held to the
// base directory.
#include "renderer/gltf_loader.hpp"
#include "renderer/gltf_validate.hpp"

#include "common/error.hpp"
#include "gltf_test_files.hpp"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <iterator>

using namespace signstim;
using namespace signstim::render;
using namespace signstim::render::testing;
namespace fs = std::filesystem;

namespace {

fs::path testDir() { return freshTestDir("gltf_validate"); }

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// The InputError `load` throws (fails the test if it throws none).
InputError refusal(const std::function<void()>& load) {
    try {
        load();
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "accepted";
    return InputError("", 0, "", "accepted");
}

// A box in the layout of the Khronos sample "Box": 24 vertices (4 per face, each face with
// its own normal), 36 unsigned short indices, one material, a root node whose matrix turns
// Z-up into Y-up and a child node showing the mesh.
GltfBuilder boxGltf() {
    GltfBuilder b;
    std::vector<float> positions, normals;
    std::vector<std::uint16_t> indices;
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {-1.0f, 1.0f}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const auto first = static_cast<std::uint16_t>(positions.size() / 3);
            for (float cu : {-0.5f, 0.5f})
                for (float cv : {-0.5f, 0.5f}) {
                    float p[3], n[3] = {0, 0, 0};
                    p[axis] = 0.5f * side;
                    p[u] = cu;
                    p[v] = side > 0 ? cv : -cv;  // counter-clockwise seen from outside
                    n[axis] = side;
                    positions.insert(positions.end(), p, p + 3);
                    normals.insert(normals.end(), n, n + 3);
                }
            for (int k : {0, 1, 3, 0, 3, 2}) indices.push_back(static_cast<std::uint16_t>(first + k));
        }
    const int position = b.addFloats(positions, "VEC3", 3);
    const int normal = b.addFloats(normals, "VEC3", 3);
    const int index = b.addAccessor(b.addView(indices), 5123, indices.size(), "SCALAR");
    b.doc["accessors"][position]["min"] = {-0.5, -0.5, -0.5};
    b.doc["accessors"][position]["max"] = {0.5, 0.5, 0.5};
    b.doc["materials"] = {{{"name", "Red"},
                           {"pbrMetallicRoughness",
                            {{"baseColorFactor", {0.8, 0.0, 0.0, 1.0}}, {"metallicFactor", 0.0}}}}};
    b.doc["meshes"] = {{{"name", "Mesh"},
                        {"primitives", {{{"attributes", {{"NORMAL", normal}, {"POSITION", position}}},
                                         {"indices", index},
                                         {"material", 0},
                                         {"mode", 4}}}}}};
    b.doc["nodes"] = {{{"children", {1}}, {"matrix", {1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1}}},
                      {{"mesh", 0}}};
    b.doc["scenes"] = {{{"nodes", {0}}}};
    b.doc["scene"] = 0;
    return b;
}

}  // namespace

TEST(GltfValidate, KhronosStyleBoxValidatesFromMemory) {
    const fs::path dir = testDir();
    for (const Container container : {Container::Embedded, Container::Glb}) {
        const fs::path path = boxGltf().write(dir, container == Container::Glb ? "Box.glb" : "Box.gltf", container);
        std::string bytes = readBytes(path);
        fs::remove(path);  // the bytes alone: nothing is read from disk
        std::vector<std::string> warnings;
        const ValidatedGltf gltf = validateGltfBytes(bytes, "Box", dir, GltfLoadOptions{}, &warnings);
        EXPECT_EQ(gltf.fileName(), "Box");
        EXPECT_TRUE(warnings.empty()) << warnings.front();
        const tinygltf::Model& model = gltf.model();
        ASSERT_EQ(model.accessors.size(), 3u);
        EXPECT_EQ(model.nodes.size(), 2u);
        EXPECT_EQ(model.meshes[0].primitives[0].indices, 2);
        const std::vector<double> indices =
            gltf.readAccessor(2, {TINYGLTF_TYPE_SCALAR}, {TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT}, "indices");
        ASSERT_EQ(indices.size(), 36u);
        EXPECT_EQ(indices[35], 22.0);  // last face: first vertex 20, corner 2

        const Scene scene = loadGltfBytes(std::move(bytes), "Box", dir, GltfLoadOptions{});
        EXPECT_EQ(scene.sourceName, "Box");
        ASSERT_EQ(scene.meshes.size(), 1u);
        const Primitive& box = scene.meshes[0].primitives[0];
        EXPECT_EQ(box.vertices.size(), 24u);
        EXPECT_EQ(box.indices.size(), 36u);
        EXPECT_EQ(box.vertices[23].normal, glm::vec3(0, 0, 1));
        EXPECT_EQ(scene.roots, std::vector<int>{0});
        EXPECT_TRUE(scene.nodes[0].restMatrix.has_value());
        EXPECT_EQ(scene.nodes[1].parent, 0);
        EXPECT_FLOAT_EQ(scene.materials[0].baseColorFactor.r, 0.8f);
    }
}

TEST(GltfValidate, BrokenBytesAreRefusedAsTheFileIs) {
    const fs::path dir = testDir();
    const std::string glb = readBytes(triangleGltf().write(dir, "tri.glb", Container::Glb));
    std::string gltf = readBytes(triangleGltf().write(dir, "tri.gltf", Container::Embedded));
    const std::size_t oops = gltf.find("\"meshes\"");
    gltf.insert(oops, "\"oops\" ");  // a JSON syntax error, a few lines down
    const int oopsLine = 1 + static_cast<int>(std::count(gltf.begin(), gltf.begin() + static_cast<long>(oops), '\n'));
    ASSERT_GT(oopsLine, 1);
    // Each broken input as a file, then from memory under the file's name: the same error,
    // field and line.
    const std::vector<std::pair<std::string, std::string>> broken = {
        {"cut.glb", glb.substr(0, glb.size() - 10)},  // the BIN chunk cut short
        {"header.glb", glb.substr(0, 15)},            // shorter than the GLB header
        {"json.glb", glb.substr(0, 40)},              // the JSON chunk cut short
        {"syntax.gltf", gltf},
        {"empty.gltf", ""},
    };
    for (const auto& entry : broken) {
        const std::string& name = entry.first;  // not a structured binding: clang 14 cannot capture one
        const std::string& bytes = entry.second;
        const fs::path path = dir / name;
        std::ofstream(path, std::ios::binary) << bytes;
        const InputError fromFile = refusal([&] { loadGltf(path); });
        const InputError fromMemory =
            refusal([&] { validateGltfBytes(bytes, path.string(), path.parent_path(), GltfLoadOptions{}); });
        EXPECT_STREQ(fromMemory.what(), fromFile.what()) << name;
        EXPECT_EQ(fromMemory.field(), fromFile.field()) << name;
        EXPECT_EQ(fromMemory.line(), fromFile.line()) << name;
        EXPECT_EQ(fromMemory.file(), path.string()) << name;
    }
    // What the messages say (so that equal messages are not equally empty).
    const InputError cut = refusal([&] { loadGltfBytes(glb.substr(0, glb.size() - 10), "cut.glb", dir, {}); });
    EXPECT_EQ(cut.what(), "cut.glb: field 'glb.length': truncated .glb: header declares " + std::to_string(glb.size()) +
                              " bytes but the file has " + std::to_string(glb.size() - 10));
    EXPECT_EQ(refusal([&] { loadGltfBytes(gltf, "syntax.gltf", dir, {}); }).line(), oopsLine);
    EXPECT_EQ(refusal([&] { loadGltfBytes("", "empty.gltf", dir, {}); }).detail(), "file is empty");
}

TEST(GltfValidate, AccessorsAreCheckedWhenRead) {
    GltfBuilder b = triangleGltf();
    b.doc["accessors"][0]["count"] = 1000;  // POSITION reads past its bufferView
    const fs::path path = b.write(testDir(), "long.gltf", Container::Embedded);
    const ValidatedGltf gltf = validateGltfBytes(readBytes(path), "long.gltf", path.parent_path(), GltfLoadOptions{});
    const InputError error = refusal([&] { gltf.checkAccessor(0); });
    EXPECT_EQ(error.field(), "/accessors/0/count");
    EXPECT_NE(error.detail().find("reads past the end of /bufferViews/0"), std::string::npos) << error.what();
    EXPECT_NO_THROW(gltf.checkAccessor(1));
    EXPECT_EQ(refusal([&] { loadGltfBytes(readBytes(path), "long.gltf", path.parent_path(), {}); }).field(),
              "/accessors/0/count");
}

TEST(GltfValidate, UrisResolveAgainstAndStayInsideTheBaseDirectory) {
    const fs::path dir = testDir();
    const fs::path base = dir / "model";
    GltfBuilder b = triangleGltf();
    const fs::path written = b.write(base, "model.gltf", Container::ExternalBuffer);  // + model/model.gltf.bin
    nlohmann::json doc = nlohmann::json::parse(readBytes(written));
    fs::remove(written);
    auto withUri = [&](const std::string& uri) {
        doc["buffers"][0]["uri"] = uri;
        return doc.dump();
    };

    // Inside the base directory: found there, wherever the working directory is.
    const Scene scene = loadGltfBytes(withUri("model.gltf.bin"), "in-memory.gltf", base, GltfLoadOptions{});
    EXPECT_EQ(scene.meshes[0].primitives[0].vertices.size(), 3u);
    // The same bytes against another base directory: the buffer is looked for there.
    InputError error = refusal([&] { validateGltfBytes(withUri("model.gltf.bin"), "in-memory.gltf", dir, {}); });
    EXPECT_EQ(error.field(), "/buffers/0/uri");
    EXPECT_NE(error.detail().find((fs::canonical(dir) / "model.gltf.bin").string() + "' not found"), std::string::npos)
        << error.what();

    // Out of the base directory, although the file exists: refused, naming the folder.
    fs::create_directories(dir / "outside");
    fs::copy_file(base / "model.gltf.bin", dir / "outside" / "data.bin");
    GltfLoadOptions options;
    options.allowFlag = "--allow-dir";
    error = refusal([&] { validateGltfBytes(withUri("../outside/data.bin"), "in-memory.gltf", base, options); });
    EXPECT_EQ(error.file(), "in-memory.gltf");
    EXPECT_EQ(error.field(), "/buffers/0/uri");
    EXPECT_NE(error.detail().find("leads out of the model's folder " + fs::canonical(base).string()),
              std::string::npos)
        << error.what();
    EXPECT_NE(error.detail().find("--allow-dir"), std::string::npos) << error.what();
    const std::string absolute = fs::absolute(dir / "outside" / "data.bin").string();
    error = refusal([&] { loadGltfBytes(withUri(absolute), "abs.gltf", base, {}); });
    EXPECT_NE(error.detail().find("is an absolute path"), std::string::npos) << error.what();
    // ... unless the user allowed that folder.
    options.allowedDirectories = {dir / "outside"};
    EXPECT_NO_THROW(validateGltfBytes(withUri("../outside/data.bin"), "in-memory.gltf", base, options));
}

// Found by the fuzzer (tests/fuzz/regressions/gltf_*/number-overflow-406): a number beyond a
// double was nlohmann's out_of_range escaping as an internal error (exit 4). It is bad input,
// named with its line, in .gltf and .glb alike.
TEST(GltfValidate, NumberBeyondADoubleIsBadInputNamingItsLine) {
    const std::string text = "{\"asset\": {\"version\": \"2.0\"},\n \"scene\": 1e400}";
    const InputError error = refusal([&] { validateGltfBytes(text, "big.gltf", {}, {}); });
    EXPECT_EQ(error.file(), "big.gltf");
    EXPECT_EQ(error.line(), 2);
    EXPECT_NE(std::string(error.what()).find("'1e400'"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("does not fit a double"), std::string::npos) << error.what();
}

// Issue 25 §10: 10^5 nested arrays (200 KB) are refused at the depth limit, before a deep
// value is built (its recursive destruction alone would overflow the stack); 64 levels pass.
TEST(GltfValidate, NestingBeyondTheDepthLimitIsBadInput) {
    const auto nested = [](std::size_t depth) {
        return "{\"asset\": {\"version\": \"2.0\"}, \"extras\": " + std::string(depth, '[') + std::string(depth, ']') + "}";
    };
    const InputError error = refusal([&] { validateGltfBytes(nested(100000), "deep.gltf", {}, {}); });
    EXPECT_EQ(error.file(), "deep.gltf");
    EXPECT_NE(std::string(error.what()).find("nested more than 64 deep"), std::string::npos) << error.what();
    EXPECT_NO_THROW(validateGltfBytes(nested(60), "shallow.gltf", {}, {}));
}
