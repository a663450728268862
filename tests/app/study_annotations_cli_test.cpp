// `signstim study` writes, beside every clip, its eye-tracking regions (regions/NAME.csv) and
// its ELAN file (elan/NAME.eaf) as files of the unit: listed in the manifest with what the clip
// shows, one CSV row per frame, panel and region inside the clip's panel, an .eaf pointing at
// the clip; switched off by the study's outputs (docs/study.md, "Eye-tracking regions", "ELAN
// files"). Resume, verify and shards treat them as every unit file (study_cli_test.cpp's runs
// compare whole folders byte for byte, these included).
#include "tests/app/run_command.hpp"
#include "tests/app/study_reference_run.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;
using signstim::test::Capture;
using signstim::test::readFile;
using signstim::test::runShell;
using signstim::test::runSignstim;
using signstim::test::shellQuote;

const std::string kScenes = fs::path(SIGNSTIM_SOURCE_DIR).append("scenes").string();
const fs::path kData = fs::path(SIGNSTIM_SOURCE_DIR).append("tests/app/data");

fs::path render(const std::string& file, const std::string& name) {
    const fs::path dir = signstim::test::freshDir(SIGNSTIM_BINARY_DIR, "study_annotations_cli_test", name, false);
    const auto r = runSignstim("study " + shellQuote((kData / file).string()) + " --quiet --out " + shellQuote(dir.string()) +
                                   " --scenes " + shellQuote(kScenes),
                               Capture::StdoutAndStderr, "SIGNSTIM_VALIDATION=1");
    EXPECT_EQ(r.status, 0) << r.output;
    return dir;
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream in(line);
    std::string field;
    while (std::getline(in, field, ',')) fields.push_back(field);
    if (!line.empty() && line.back() == ',') fields.emplace_back();
    return fields;
}

TEST(StudyAnnotationsCli, EveryClipHasRegionsAndAnElanFileListedBesideIt) {
    // The small study as render() would make it, rendered once for this and StudyCli's tests
    // that compare against it (tests/app/study_reference_run.hpp; read only here).
    const fs::path& dir = signstim::test::smallStudyReferenceRun();
    const nlohmann::json manifest = nlohmann::json::parse(readFile(dir / "manifest.json"));
    std::map<std::string, nlohmann::json> byPath;
    for (const auto& f : manifest["files"]) byPath[f["path"].get<std::string>()] = f;
    const auto clips = [&] {
        std::vector<nlohmann::json> all;
        for (const auto& story : manifest["study"]["stories"])
            for (const auto& clip : story["clips"]) all.push_back(clip);
        for (const auto& sentence : manifest["study"]["sentences"]) all.push_back(sentence["clip"]);
        return all;
    }();
    ASSERT_EQ(clips.size(), 4u * 4 + 4);
    const bool xmllint = runShell("command -v xmllint").status == 0;
    for (const auto& clip : clips) {
        const std::string video = clip["video"], regions = clip["regions"], annotation = clip["annotation"];
        ASSERT_TRUE(byPath.count(regions)) << regions;
        ASSERT_TRUE(byPath.count(annotation)) << annotation;
        EXPECT_EQ(byPath[regions]["kind"], "regions");
        EXPECT_EQ(byPath[annotation]["kind"], "annotation");
        const nlohmann::json& shows = byPath[video]["shows"];
        EXPECT_EQ(byPath[regions]["shows"], shows);
        const std::uint64_t frames = byPath[video]["frames"];
        // Panels: 1 (a story's clip) or the side-by-side clip's, in the renderer's grid of 96x72.
        const std::size_t panels = shows.contains("panels") ? shows["panels"].size() : 1;
        const int columns = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(panels))));
        const int rows = static_cast<int>((panels + columns - 1) / columns);

        std::stringstream csv(readFile(dir / regions));
        std::string line;
        std::getline(csv, line);
        EXPECT_EQ(line, "frame,time_ms,panel,region,x0,y0,x1,y1,visible");
        std::uint64_t count = 0, visibleFaces = 0;
        while (std::getline(csv, line)) {
            const std::vector<std::string> f = split(line);
            ASSERT_EQ(f.size(), 9u) << regions << ": " << line;
            EXPECT_EQ(std::stoull(f[0]), count / (4 * panels)) << line;  // frame after frame, 4 regions per panel
            ++count;
            EXPECT_EQ(std::stoll(f[1]), std::llround(std::stod(f[0]) * 1000.0 / 4.0)) << line;  // 4 fps
            EXPECT_EQ(f[2].empty(), panels == 1) << line;
            if (f[8] != "1") continue;
            const std::size_t k = panels == 1 ? 0 : static_cast<std::size_t>(f[2][0] - 'A');
            const int cx0 = static_cast<int>(k % columns) * 96 / columns, cx1 = static_cast<int>(k % columns + 1) * 96 / columns;
            const int cy0 = static_cast<int>(k / columns) * 72 / rows, cy1 = static_cast<int>(k / columns + 1) * 72 / rows;
            EXPECT_GE(std::stoi(f[4]), cx0) << line;
            EXPECT_LE(std::stoi(f[6]), cx1) << line;
            EXPECT_GE(std::stoi(f[5]), cy0) << line;
            EXPECT_LE(std::stoi(f[7]), cy1) << line;
            EXPECT_LT(std::stoi(f[4]), std::stoi(f[6])) << line;
            visibleFaces += f[3] == "face";
        }
        EXPECT_EQ(count, frames * panels * 4) << regions;
        EXPECT_EQ(visibleFaces, frames * panels) << "the face is always in view: " << regions;

        const std::string eaf = readFile(dir / annotation);
        EXPECT_NE(eaf.find("RELATIVE_MEDIA_URL=\"../" + video + "\""), std::string::npos) << annotation;
        EXPECT_NE(eaf.find(panels == 1 ? "TIER_ID=\"verb\"" : "TIER_ID=\"verb A\""), std::string::npos) << annotation;
        if (xmllint) {
            EXPECT_EQ(runShell("xmllint --noout " + shellQuote((dir / annotation).string())).status, 0) << annotation;
        }
    }
    EXPECT_EQ(runSignstim("study verify " + shellQuote(dir.string())).status, 0);
}

TEST(StudyAnnotationsCli, OutputsSwitchThemOff) {
    const fs::path dir = render("no-annotations.json", "off");
    EXPECT_FALSE(fs::exists(dir / "regions"));
    EXPECT_FALSE(fs::exists(dir / "elan"));
    const nlohmann::json manifest = nlohmann::json::parse(readFile(dir / "manifest.json"));
    for (const auto& f : manifest["files"]) {
        EXPECT_NE(f["kind"], "regions");
        EXPECT_NE(f["kind"], "annotation");
    }
    EXPECT_EQ(manifest["study"]["stories"][0]["clips"][0]["regions"], "");
}

TEST(StudyAnnotationsCli, StoryWritesRegionsAndElanFileBesideItsMp4) {
    const fs::path dir = signstim::test::freshDir(SIGNSTIM_BINARY_DIR, "study_annotations_cli_test", "story", false);
    const std::string story = shellQuote(kScenes + "/stories/examples/the-question.json");
    const auto r = runSignstim("story " + story + " --version vector --size 96x72 --fps 5 --msaa 1 --quiet --annotations --out " +
                               shellQuote((dir / "q.mp4").string()) + " --scenes " + shellQuote(kScenes));
    ASSERT_EQ(r.status, 0) << r.output;
    const std::uint64_t frames = std::stoull(r.output.substr(r.output.find("(vector), ") + 10));
    std::stringstream csv(readFile(dir / "q.regions.csv"));
    std::string line;
    std::uint64_t rows = 0;
    std::getline(csv, line);
    while (std::getline(csv, line)) ++rows;
    EXPECT_EQ(rows, frames * 4) << r.output;
    const std::string eaf = readFile(dir / "q.eaf");
    EXPECT_NE(eaf.find("RELATIVE_MEDIA_URL=\"./q.mp4\""), std::string::npos);
    EXPECT_NE(eaf.find("(vector)</ANNOTATION_VALUE>"), std::string::npos);
    // A still has no frames to annotate: refused as a flag's mistake.
    EXPECT_EQ(runSignstim("story " + story + " --version vector --annotations --out " + shellQuote((dir / "q.png").string()) +
                          " --scenes " + shellQuote(kScenes))
                  .status,
              1);
}

}  // namespace
