// End-to-end tests of `signstim render-gltf` (runs the real binary on Vulkan, with the
// validation layer on: SIGNSTIM_VALIDATION=1). Input files are built here (synthetic arm).
#include "renderer/gltf_writer.hpp"
#include "renderer/image_io.hpp"
#include "tests/app/run_command.hpp"
#include "tests/renderer/gltf_test_files.hpp"
#include "tests/renderer/morph_test_files.hpp"

#include <gtest/gtest.h>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <fstream>

using namespace signstim::render;
namespace fs = std::filesystem;

namespace {

fs::path testDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir = fs::path(SIGNSTIM_BINARY_DIR) / "test-tmp" / "render_gltf" / info->name();
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

using Result = signstim::test::CommandResult;

// The signstim binary with the Vulkan validation layer on; stdout and stderr together.
Result runSignstim(const std::string& arguments) {
    return signstim::test::runSignstim(arguments, signstim::test::Capture::StdoutAndStderr, "SIGNSTIM_VALIDATION=1");
}

std::string q(const fs::path& path) { return signstim::test::shellQuote(path.string()); }

// A skinned cylinder (radius 0.1, height 1) on two joints; the lower joint bends 90° about Z
// over one second (LINEAR). Synthetic test geometry.
Scene armScene() {
    Scene scene;
    scene.nodes.resize(3);
    scene.nodes[0].name = "upper";
    scene.nodes[0].children = {1};
    scene.nodes[1].name = "lower";
    scene.nodes[1].parent = 0;
    scene.nodes[1].rest.translation = {0, 0.5f, 0};
    scene.nodes[2].name = "arm";
    scene.nodes[2].mesh = 0;
    scene.nodes[2].skin = 0;
    scene.roots = {0, 2};
    Primitive p;
    p.skinned = true;
    p.material = 0;
    const int segments = 16, rings = 10;
    for (int r = 0; r <= rings; ++r) {
        const float y = static_cast<float>(r) / rings;
        const float w = std::clamp((y - 0.4f) / 0.2f, 0.0f, 1.0f);  // blend around the joint
        for (int s = 0; s < segments; ++s) {
            const float a = 6.2831853f * static_cast<float>(s) / segments;
            Vertex v;
            v.position = {0.1f * std::cos(a), y, 0.1f * std::sin(a)};
            v.normal = {std::cos(a), 0, std::sin(a)};
            v.joints = {0, 1, 0, 0};
            v.weights = {1.0f - w, w, 0, 0};
            p.vertices.push_back(v);
        }
    }
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const std::uint32_t a = r * segments + s, b = r * segments + (s + 1) % segments;
            const std::uint32_t c = a + segments, d = b + segments;
            p.indices.insert(p.indices.end(), {a, c, b, b, c, d});
        }
    scene.meshes.push_back(Mesh{"arm", {p}});
    Material m;
    m.baseColorFactor = {0.8f, 0.35f, 0.25f, 1.0f};
    m.metallicFactor = 0.0f;
    m.roughnessFactor = 0.6f;
    scene.materials.push_back(m);
    Skin skin;
    skin.joints = {0, 1};
    skin.inverseBindMatrices = {glm::mat4(1.0f), glm::mat4(1.0f)};
    skin.inverseBindMatrices[1][3][1] = -0.5f;
    scene.skins.push_back(skin);
    Animation bend;
    bend.name = "bend";
    const glm::quat end = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 0, 1));
    bend.samplers.push_back({{0.0f, 1.0f}, {{0, 0, 0, 1}, {end.x, end.y, end.z, end.w}}, Interpolation::Linear});
    bend.channels.push_back({1, AnimationPath::Rotation, 0});
    bend.durationSeconds = 1.0f;
    scene.animations.push_back(bend);
    return scene;
}

fs::path writeArm(const fs::path& dir) {
    const fs::path path = dir / "arm.glb";
    writeGltf(armScene(), path);
    return path;
}

std::size_t differingPixels(const Image& a, const Image& b) {
    std::size_t n = 0;
    for (std::size_t p = 0; p + 3 < a.bytes.size() && p + 3 < b.bytes.size(); p += 4)
        n += a.bytes[p] != b.bytes[p] || a.bytes[p + 1] != b.bytes[p + 1] || a.bytes[p + 2] != b.bytes[p + 2];
    return n;
}

}  // namespace

TEST(RenderGltfCli, PngOutputShowsTheModel) {
    const fs::path dir = testDir();
    const fs::path out = dir / "arm.png";
    const Result r = runSignstim("render-gltf " + q(writeArm(dir)) + " --out " + q(out) + " --size 160x120 --quiet");
    ASSERT_EQ(r.status, 0) << r.output;
    const Image image = readImage(out);
    EXPECT_EQ(image.width, 160u);
    EXPECT_EQ(image.height, 120u);
    // The arm covers part of the frame: pixels differ from the corner (background) colour.
    Image corner = image;
    for (std::size_t p = 0; p < corner.bytes.size(); p += 4) std::copy_n(image.bytes.begin(), 4, corner.bytes.begin() + p);
    const std::size_t covered = differingPixels(image, corner);
    EXPECT_GT(covered, 160u * 120u / 50);
    EXPECT_LT(covered, 160u * 120u / 2);
}

TEST(RenderGltfCli, DirectoryOutputSamplesTheAnimation) {
    const fs::path dir = testDir();
    const fs::path out = dir / "frames";
    const Result r = runSignstim("render-gltf " + q(writeArm(dir)) + " --out " + q(out) +
                              " --size 96x96 --frames 3 --msaa 1 --background '#ffffff'");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("3/3 frames"), std::string::npos) << r.output;  // progress on stderr
    for (const char* name : {"frame_00001.png", "frame_00002.png", "frame_00003.png"})
        EXPECT_TRUE(fs::exists(out / name)) << name;
    EXPECT_FALSE(fs::exists(out / "frame_00004.png"));
    // The arm bends between the first and the last frame.
    EXPECT_GT(differingPixels(readImage(out / "frame_00001.png"), readImage(out / "frame_00003.png")), 50u);
}

TEST(RenderGltfCli, MorphWeightsAnimationChangesTheShapeOverTheFrames) {
    const fs::path dir = testDir();
    signstim::render::testing::MorphBox box = signstim::render::testing::morphBox();
    const fs::path model = box.gltf.write(dir, "morph-box.gltf", signstim::render::testing::Container::Embedded);
    const fs::path out = dir / "frames";
    const Result r = runSignstim("render-gltf " + q(model) + " --out " + q(out) +
                                 " --size 96x96 --frames 3 --msaa 1 --animation morph");
    ASSERT_EQ(r.status, 0) << r.output;
    // The weights go 0 -> 1: the box stretches and pinches between the first and last frame.
    EXPECT_GT(differingPixels(readImage(out / "frame_00001.png"), readImage(out / "frame_00003.png")), 50u);
}

TEST(RenderGltfCliRefuses, MorphTargetCountNotMatchingItsWeights) {
    const fs::path dir = testDir();
    signstim::render::testing::MorphBox box = signstim::render::testing::morphBox();
    box.gltf.doc["meshes"][0]["weights"] = {0.5, 0.5, 0.5};
    const fs::path model = box.gltf.write(dir, "morph-box.gltf", signstim::render::testing::Container::Embedded);
    const Result r = runSignstim("render-gltf " + q(model) + " --out " + q(dir / "out.png") + " --size 32x32");
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("morph-box.gltf"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("/meshes/0/weights"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST(RenderGltfCli, Mp4OutputIsH264AtTheRequestedRate) {
    const fs::path dir = testDir();
    const fs::path out = dir / "arm.mp4";
    const Result r = runSignstim("render-gltf " + q(writeArm(dir)) + " --out " + q(out) +
                              " --size 128x96 --fps 30000/1001 --quiet");
    ASSERT_EQ(r.status, 0) << r.output;
    const std::string probe = signstim::test::runShell("ffprobe -v error -count_frames -show_entries "
                                                       "stream=codec_name,pix_fmt,nb_read_frames,r_frame_rate "
                                                       "-of default=noprint_wrappers=1 " + q(out))
                                  .output;
    EXPECT_NE(probe.find("codec_name=h264"), std::string::npos) << probe;
    EXPECT_NE(probe.find("pix_fmt=yuv420p"), std::string::npos) << probe;
    // 1 s at 29.97 fps: ceil(29.97) + 1 = 31 frames, first and last key included.
    EXPECT_NE(probe.find("nb_read_frames=31"), std::string::npos) << probe;
    EXPECT_NE(probe.find("r_frame_rate=30000/1001"), std::string::npos) << probe;
}

TEST(RenderGltfCli, UnwritableOutputIsRefusedBeforeRendering) {
    const fs::path dir = testDir();
    std::ofstream(dir / "plain-file") << "x";
    const fs::path out = dir / "plain-file" / "a.png";
    const Result r = runSignstim("render-gltf " + q(writeArm(dir)) + " --out " + q(out));
    // A write the system refuses is exit 3 with its reason (docs/errors.md).
    EXPECT_EQ(r.status, 3) << r.output;
    EXPECT_NE(r.output.find("plain-file/a.png: cannot write: Not a directory"), std::string::npos) << r.output;
}

TEST(RenderGltfCli, UnknownAnimationListsTheAvailableOnes) {
    const fs::path dir = testDir();
    const Result r = runSignstim("render-gltf " + q(writeArm(dir)) + " --out " + q(dir / "x.png") + " --animation wave");
    EXPECT_EQ(r.status, 1) << r.output;  // a flag's value: usage
    EXPECT_NE(r.output.find("'bend'"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "x.png"));
}

// Each broken input: exit status 2, a message naming the file and the problem, no output.
namespace {

void expectBrokenInputRefused(const fs::path& input, const std::string& problem) {
    const fs::path out = input.parent_path() / "out";
    for (const fs::path& target : {out / "a.png", out / "seq", out / "v.mp4"}) {
        const Result r = runSignstim("render-gltf " + q(input) + " --out " + q(target) + " --size 64x64");
        EXPECT_EQ(r.status, 2) << r.output;
        EXPECT_NE(r.output.find(input.filename().string()), std::string::npos) << r.output;
        EXPECT_NE(r.output.find(problem), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(out)) << "output written for " << input;
    }
}

std::string readAll(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// The arm as an embedded .gltf, with `from` replaced by `to` in its JSON.
fs::path editedArm(const fs::path& dir, const std::string& from, const std::string& to) {
    const fs::path path = dir / "arm.gltf";
    writeGltf(armScene(), path);
    std::string text = readAll(path);
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

}  // namespace

TEST(RenderGltfCliRefuses, MissingFile) { expectBrokenInputRefused(testDir() / "absent.glb", "not found"); }

TEST(RenderGltfCliRefuses, Directory) {
    const fs::path dir = testDir() / "dir.gltf";
    fs::create_directories(dir);
    expectBrokenInputRefused(dir, "directory");
}

TEST(RenderGltfCliRefuses, TruncatedGlb) {
    const fs::path path = writeArm(testDir());
    fs::resize_file(path, fs::file_size(path) / 2);
    expectBrokenInputRefused(path, "truncated");
}

TEST(RenderGltfCliRefuses, RandomBytes) {
    const fs::path path = testDir() / "noise.glb";
    std::ofstream out(path, std::ios::binary);
    std::uint32_t state = 2463534242u;  // fixed xorshift seed
    for (int i = 0; i < 2048; ++i) {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        out.put(static_cast<char>(state));
    }
    out.close();
    expectBrokenInputRefused(path, "not a glTF file");
}

TEST(RenderGltfCliRefuses, BufferIndexOutOfRange) {
    expectBrokenInputRefused(editedArm(testDir(), "\"buffer\": 0", "\"buffer\": 5"), "out of range");
}

TEST(RenderGltfCliRefuses, BufferViewIndexOutOfRange) {
    expectBrokenInputRefused(editedArm(testDir(), "\"bufferView\": 0", "\"bufferView\": 99"), "out of range");
}

TEST(RenderGltfCliRefuses, AccessorIndexOutOfRange) {
    expectBrokenInputRefused(editedArm(testDir(), "\"POSITION\": 0", "\"POSITION\": 77"), "out of range");
}

TEST(RenderGltfCliRefuses, AccessorReadingPastItsBuffer) {
    expectBrokenInputRefused(editedArm(testDir(), "\"count\": 176", "\"count\": 17600"), "past the end");
}

TEST(RenderGltfCliRefuses, AbsurdByteLength) {
    const fs::path dir = testDir();
    const fs::path path = dir / "arm.gltf";
    writeGltf(armScene(), path);
    std::string text = readAll(path);
    const std::size_t at = text.rfind("\"byteLength\": ");  // the buffer's, written last
    ASSERT_NE(at, std::string::npos);
    const std::size_t end = text.find_first_of(",\n}", at + 14);
    text.replace(at, end - at, "\"byteLength\": 1000000000000");
    std::ofstream(path, std::ios::binary) << text;
    expectBrokenInputRefused(path, "exceeds");
}

TEST(RenderGltfCliRefuses, RequiredExtension) {
    signstim::render::testing::GltfBuilder b = signstim::render::testing::triangleGltf();
    b.doc["extensionsUsed"] = b.doc["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    expectBrokenInputRefused(b.write(testDir(), "draco.gltf", signstim::render::testing::Container::Embedded),
                             "KHR_draco_mesh_compression");
}

TEST(RenderGltfCliRefuses, BufferOutsideTheModelsFolderUnlessAllowed) {
    const fs::path dir = testDir();
    const fs::path model = signstim::render::testing::triangleGltf().write(
        dir / "model", "tri.gltf", signstim::render::testing::Container::ExternalBuffer);
    fs::create_directories(dir / "lab-data");
    fs::rename(dir / "model" / "tri.gltf.bin", dir / "lab-data" / "tri.bin");
    nlohmann::json doc = nlohmann::json::parse(std::ifstream(model));
    doc["buffers"][0]["uri"] = "../lab-data/tri.bin";
    std::ofstream(model) << doc.dump();
    expectBrokenInputRefused(model, "--allow-dir");  // the message says how to allow it
    const fs::path out = dir / "out" / "tri.png";
    const Result r = runSignstim("render-gltf " + q(model) + " --out " + q(out) + " --size 32x32 --quiet --allow-dir " +
                                 q(dir / "lab-data"));
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_TRUE(fs::exists(out));
}

// A key at 1e9 s made 0/-2147483647 frames, an empty folder and exit status 0.
TEST(RenderGltfCliRefuses, AnimationLongerThanAnHour) {
    const fs::path dir = testDir();
    const fs::path model = signstim::render::testing::animatedTriangleGltf({0.0f, 1e9f}).write(
        dir, "long.gltf", signstim::render::testing::Container::Embedded);
    for (const char* target : {"seq", "v.mp4"}) {
        const Result r = runSignstim("render-gltf " + q(model) + " --out " + q(dir / "out" / target) + " --size 32x32");
        EXPECT_EQ(r.status, 2) << r.output;
        EXPECT_NE(r.output.find("long.gltf: field '/accessors/2'"), std::string::npos) << r.output;
        EXPECT_NE(r.output.find("30000000001 frames at 30 fps, more than one hour (108001 frames)"), std::string::npos)
            << r.output;
        EXPECT_FALSE(fs::exists(dir / "out")) << r.output;
    }
    // --frames spreads a given number of frames over it; more than an hour's worth is a usage error.
    const Result tooMany = runSignstim("render-gltf " + q(model) + " --out " + q(dir / "out" / "seq") +
                                       " --size 32x32 --frames 200000 --fps 25");
    EXPECT_EQ(tooMany.status, 1) << tooMany.output;
    EXPECT_NE(tooMany.output.find("--frames"), std::string::npos) << tooMany.output;
    EXPECT_NE(tooMany.output.find("1 to 90001"), std::string::npos) << tooMany.output;
    EXPECT_FALSE(fs::exists(dir / "out"));
    const Result few = runSignstim("render-gltf " + q(model) + " --out " + q(dir / "out" / "seq") +
                                   " --size 32x32 --msaa 1 --frames 3 --quiet");
    EXPECT_EQ(few.status, 0) << few.output;
    EXPECT_TRUE(fs::exists(dir / "out" / "seq" / "frame_00003.png"));
}

TEST(RenderGltfCliRefuses, CameraThatCannotViewNamesTheFlag) {
    const fs::path dir = testDir();
    // Looking straight down the up vector: no view direction is defined.
    const Result r = runSignstim("render-gltf " + q(writeArm(dir)) + " --out " + q(dir / "out" / "x.png") +
                                 " --camera 'eye=0,5,0;target=0,0,0;up=0,1,0'");
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("--camera"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("<frame>"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out"));
}
