// One rule for every subcommand's command line: a flag mistake is a usage error, exit status
// 1, with a message naming the flag, and nothing is written. Table-driven over the commands
// that render (the built binary, validation layer on).
#include "tests/app/run_command.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using signstim::test::shellQuote;

const std::string kScenes = shellQuote((fs::path(SIGNSTIM_SOURCE_DIR) / "scenes").string());

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(SIGNSTIM_BINARY_DIR) / "test-tmp" / "cli_rules" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

signstim::test::CommandResult run(const std::string& arguments) {
    return signstim::test::runSignstim(arguments, signstim::test::Capture::StdoutAndStderr, "SIGNSTIM_VALIDATION=1");
}

struct RenderCommand {
    std::string name;
    // The command with a valid command line writing under `out` (which must stay absent).
    std::string (*line)(const fs::path& out);
    std::string sizeFlag;  // its image size flag, with a value of zero
};

const std::vector<RenderCommand>& renderCommands() {
    static const std::vector<RenderCommand> commands = {
        {"render-gltf",
         [](const fs::path& out) {
             return "render-gltf " + shellQuote(fs::path(SIGNSTIM_SOURCE_DIR) / "scenes" / "avatar" / "signer.glb") +
                    " --quiet --out " + shellQuote((out / "frames").string());
         },
         "--size 0x0"},
        {"verb",
         [](const fs::path& out) {
             return "verb ASK --subject 0.9 --object -0.6 --version animator --quiet --scenes " + kScenes + " --out " +
                    shellQuote((out / "ask.mp4").string());
         },
         "--size 0x0"},
        {"demo",
         [](const fs::path& out) {
             return "demo --quiet --verbs ASK --scenes " + kScenes + " --out " + shellQuote(out.string());
         },
         "--panel-size 0x0"},
        {"pose",
         [](const fs::path& out) {
             return "pose --right C --scenes " + kScenes + " --out " + shellQuote((out / "c.png").string());
         },
         "--size 0x0"},
        {"handshapes",
         [](const fs::path& out) {
             return "handshapes --scenes " + kScenes + " --gallery " + shellQuote((out / "gallery.png").string());
         },
         "--cell 0"},
    };
    return commands;
}

// Whether the device the commands choose by default renders with `samples` samples per pixel
// (lavapipe: 1 and 4). In `signstim devices`, the chosen device's line starts with '*' and
// ends with its sample counts ("1,4") and whether it is usable.
bool defaultDeviceHasSampleCount(int samples) {
    const std::string list = run("devices").output;
    const std::size_t chosen = list.find("\n* ");
    if (chosen == std::string::npos) return false;
    std::istringstream line(list.substr(chosen + 1, list.find('\n', chosen + 1) - chosen - 1));
    std::vector<std::string> words;
    for (std::string word; line >> word;) words.push_back(word);
    if (words.size() < 2) return false;
    return ("," + words[words.size() - 2] + ",").find("," + std::to_string(samples) + ",") != std::string::npos;
}

void expectUsageError(const std::string& arguments, const fs::path& out, const std::string& flag) {
    const auto r = run(arguments);
    EXPECT_EQ(r.status, 1) << arguments << "\n" << r.output;
    EXPECT_NE(r.output.find(flag), std::string::npos) << arguments << ": the message does not name " << flag << "\n"
                                                      << r.output;
    EXPECT_FALSE(fs::exists(out)) << arguments << ": left " << out << " behind";
}

}  // namespace

TEST(CliRules, TheSameFlagMistakeExitsOneInEveryRenderCommand) {
    // lavapipe has 1 and 4 samples; 3 is no Vulkan sample count on any device.
    std::vector<std::string> msaa = {"--msaa 3", "--msaa 0", "--msaa ''"};
    if (!defaultDeviceHasSampleCount(2)) msaa.push_back("--msaa 2");
    for (const RenderCommand& command : renderCommands()) {
        const fs::path dir = freshDir(command.name), out = dir / "out";
        std::vector<std::string> mistakes = msaa;
        mistakes.push_back(command.sizeFlag);
        // pose and handshapes render stills: --fps is not theirs, which is a usage error too.
        mistakes.push_back("--fps 0");
        for (const std::string& mistake : mistakes) {
            const std::string flag = mistake.substr(0, mistake.find(' '));
            expectUsageError(command.line(out) + " " + mistake, out, flag);
        }
    }
}

TEST(CliRules, EmptyOrNonDecimalNumbersAreRefused) {
    const fs::path out = freshDir("numbers") / "out";
    const std::string verb = "verb ASK --version animator --scenes " + kScenes;
    const std::string gltf = shellQuote(fs::path(SIGNSTIM_SOURCE_DIR) / "scenes" / "avatar" / "signer.glb");
    const struct {
        std::string arguments, flag;
    } cases[] = {
        // CLI11 read "" as 0: arc position 0, a valid subject.
        {verb + " --subject '' --object -0.6 --json", "--subject"},
        {verb + " --subject 0.9 --object '' --json", "--object"},
        {verb + " --subject nan --object -0.6 --json", "--subject"},
        {"demo --subject '' --scenes " + kScenes + " --out " + shellQuote(out.string()), "--subject"},
        {"render-gltf " + gltf + " --frames '' --out " + shellQuote((out / "f").string()), "--frames"},
        // --frames 0 meant "the default" before.
        {"render-gltf " + gltf + " --frames 0 --out " + shellQuote((out / "f").string()), "--frames"},
        {"render-gltf " + gltf + " --frames 0x10 --out " + shellQuote((out / "f").string()), "--frames"},
        {"handshapes --columns '' --scenes " + kScenes + " --gallery " + shellQuote((out / "g.png").string()),
         "--columns"},
        {"hand pose --shape C --hand-length '' --scenes " + kScenes, "--hand-length"},
        {"bench hand --seconds ''", "--seconds"},
    };
    for (const auto& c : cases) expectUsageError(c.arguments, out, c.flag);
}

TEST(CliRules, DemoRefusesAVerbListedTwice) {
    const fs::path out = freshDir("twice") / "out";
    const auto r = run("demo --quiet --verbs ASK,GIVE,ASK --scenes " + kScenes + " --out " + shellQuote(out.string()));
    EXPECT_EQ(r.status, 1) << r.output;
    EXPECT_NE(r.output.find("--verbs"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("ASK is listed twice"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
}

TEST(CliRules, BoneMapMistakesNameTheBoneMapFile) {
    const fs::path dir = freshDir("bone-map"), out = dir / "out";
    const fs::path map = dir / "my-bones.json";
    std::ofstream(map) << "{\n  \"bones\": {\n    \"leftUpperArm\": \"leftUpperArm\",\n"
                          "    \"rightLowerArm\": \"forearm.R\"\n  }\n}\n";
    auto r = run("pose --right C --bone-map " + shellQuote(map.string()) + " --scenes " + kScenes + " --out " +
                 shellQuote((out / "c.png").string()));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("my-bones.json:4: field '/bones/rightLowerArm'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("'forearm.R' is not in"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
    // A key that is no VRM bone (a typo) would otherwise be ignored.
    std::ofstream(map) << "{\"bones\": {\n\"rightLowerArmm\": \"rightLowerArm\"}}";
    r = run("pose --right C --bone-map " + shellQuote(map.string()) + " --scenes " + kScenes + " --out " +
            shellQuote((out / "c.png").string()));
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_NE(r.output.find("my-bones.json:2: field '/bones/rightLowerArmm'"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out));
}
