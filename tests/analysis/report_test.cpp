// Drawings rasterize as drawn and become valid, escaped SVG; the report of an analysis is the
// same bytes every time, never holds NaN or infinity, says SYNTHETIC when the data are, and
// has a figure for each of the paper's Figures 6-8 with the numbers of its tables.
#include "analysis/report.hpp"
#include "analysis/simulation.hpp"
#include "analysis/svg.hpp"
#include "analysis/text_format.hpp"
#include "renderer/drawing.hpp"
#include "tests/stimuli/review_page_fixture.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cctype>
#include <cmath>

namespace {

using namespace signstim::analysis;
using namespace signstim::render;
using signstim::stimuli::StudyListing;

const StudyListing& study() {
    static const StudyListing listing = signstim::stimuli::testing::reviewFixtureListing();
    return listing;
}

std::array<std::uint8_t, 3> pixel(const Image& image, std::uint32_t x, std::uint32_t y) {
    const std::uint8_t* p = image.bytes.data() + (static_cast<std::size_t>(y) * image.width + x) * 4;
    return {p[0], p[1], p[2]};
}

TEST(Drawing, RectanglesLinesDiscsAndTextRasterizeWhereDrawn) {
    Drawing d;
    d.width = 40;
    d.height = 30;
    d.items.push_back(DrawRect{5, 5, 10, 10, Colour{255, 0, 0}, std::nullopt, 1});
    d.items.push_back(DrawLine{0, 20.5, 40, 20.5, Colour{0, 0, 255}, 1});
    d.items.push_back(DrawDisc{30, 8, 4, Colour{0, 255, 0}, std::nullopt, 1});
    d.items.push_back(DrawText{2, 29, "I", 8, Colour{0, 0, 0}, TextAnchor::Start, false, false});
    const Image image = rasterizeDrawing(d, 2.0);
    ASSERT_EQ(image.width, 80u);
    ASSERT_EQ(image.height, 60u);
    EXPECT_EQ(pixel(image, 10, 10), (std::array<std::uint8_t, 3>{255, 0, 0}));  // rect [10, 30)
    EXPECT_EQ(pixel(image, 29, 29), (std::array<std::uint8_t, 3>{255, 0, 0}));
    EXPECT_EQ(pixel(image, 30, 30), (std::array<std::uint8_t, 3>{255, 255, 255}));
    EXPECT_EQ(pixel(image, 50, 40), (std::array<std::uint8_t, 3>{0, 0, 255}));  // line rows 40, 41
    EXPECT_EQ(pixel(image, 50, 41), (std::array<std::uint8_t, 3>{0, 0, 255}));
    EXPECT_EQ(pixel(image, 50, 42), (std::array<std::uint8_t, 3>{255, 255, 255}));
    EXPECT_EQ(pixel(image, 60, 16), (std::array<std::uint8_t, 3>{0, 255, 0}));  // disc centre
    // "I" at glyph scale 2 (size 8 at 2 pixels per unit): its stem (column 2) from 14 pixels above the baseline.
    EXPECT_EQ(pixel(image, 4 + 2 * 2, 58 - 10), (std::array<std::uint8_t, 3>{0, 0, 0}));
    EXPECT_EQ(rasterizeDrawing(d, 2.0).bytes, image.bytes);
    d.items.push_back(DrawLine{0, 0, 10, 10, Colour{}, 1});
    EXPECT_THROW(rasterizeDrawing(d, 2.0), std::invalid_argument);
}

TEST(Drawing, SvgIsEscapedWithRoundedNumbers) {
    Drawing d;
    d.width = 100;
    d.height = 50;
    d.title = "A & <B>";
    d.items.push_back(DrawText{10.004, 20.5, "p < 0.05 & \"x\"", 12, Colour{}, TextAnchor::Middle, true, true});
    d.items.push_back(DrawRect{1.256, -0.001, 3, 4, Colour{1, 2, 3}, Colour{255, 255, 255}, 1.5});
    const std::string svg = svgDocument(d);
    EXPECT_EQ(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"", 0), 0u);
    EXPECT_NE(svg.find("<title>A &amp; &lt;B&gt;</title>"), std::string::npos);
    EXPECT_NE(svg.find(">p &lt; 0.05 &amp; &quot;x&quot;</text>"), std::string::npos) << svg;
    EXPECT_NE(svg.find("x=\"10\" y=\"20.5\""), std::string::npos) << svg;
    EXPECT_NE(svg.find("transform=\"rotate(-90 10 20.5)\""), std::string::npos) << svg;
    EXPECT_NE(svg.find("<rect x=\"1.26\" y=\"0\" width=\"3\" height=\"4\" fill=\"#010203\" stroke=\"#ffffff\""), std::string::npos)
        << svg;
}

std::vector<ParticipantResults> simulated(const SimulationSettings& s, std::vector<std::string>& warnings) {
    std::vector<ParticipantResults> results;
    for (const SimulatedFile& f : simulateResults(study(), s)) results.push_back(parseResults(f.text, f.name, study(), {}, warnings));
    return results;
}

std::vector<ReportFile> report(const std::vector<ParticipantResults>& results, const std::vector<std::string>& warnings) {
    const StudyAnalysis a = analyzeStudy(study(), results, {});
    ReportInputs in;
    in.studyTitle = study().title;
    in.designHash = study().designHash;
    in.manifestName = "fixture/manifest.json";
    in.results = &results;
    in.warnings = warnings;
    return analysisReport(a, in);
}

// "nan", "inf" or "infinity" as a word of their own (not inside "unanswered" or "inflected").
bool hasNonFiniteWord(const std::string& text) {
    const auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
    for (const std::string word : {"nan", "inf", "infinity"}) {
        for (std::size_t at = 0; (at = text.find(word, at)) != std::string::npos; ++at) {
            const bool before = at > 0 && letter(text[at - 1]);
            const bool after = at + word.size() < text.size() && letter(text[at + word.size()]);
            if (!before && !after) return true;
        }
    }
    return false;
}

const ReportFile& file(const std::vector<ReportFile>& files, const std::string& path) {
    for (const ReportFile& f : files)
        if (f.path == path) return f;
    throw std::logic_error("no " + path);
}

TEST(Report, SameAnalysisSameBytesEveryFigureAndNoNonFiniteNumbers) {
    std::vector<std::string> warnings;
    const std::vector<ParticipantResults> results = simulated(plantedEffect(study(), 4), warnings);
    const std::vector<ReportFile> a = report(results, warnings), b = report(results, warnings);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].path, b[i].path);
        EXPECT_EQ(a[i].bytes, b[i].bytes) << a[i].path;
    }
    std::vector<std::string> paths;
    for (const ReportFile& f : a) paths.push_back(f.path);
    for (const char* name : {"fig6-comprehension", "fig7-likert", "fig8-likert-by-verb", "fig8b-comprehension-by-verb"}) {
        EXPECT_NE(std::find(paths.begin(), paths.end(), std::string("figures/") + name + ".svg"), paths.end()) << name;
        const std::string& png = file(a, std::string("figures/") + name + ".png").bytes;
        EXPECT_EQ(png.substr(1, 3), "PNG") << name;
        EXPECT_NE(file(a, "report.html").bytes.find(std::string("<figure id=\"") + name + "\">\n<svg"), std::string::npos) << name;
    }
    for (const ReportFile& f : a) {
        if (f.path.size() > 4 && f.path.substr(f.path.size() - 4) == ".png") continue;
        EXPECT_FALSE(hasNonFiniteWord(f.bytes)) << f.path;
        EXPECT_EQ(f.bytes.find("NaN"), std::string::npos) << f.path;
    }
    EXPECT_NE(file(a, "report.html").bytes.find("SYNTHETIC DATA"), std::string::npos);
    EXPECT_EQ(file(a, "results.csv").bytes.rfind("# SYNTHETIC DATA", 0), 0u);
    const nlohmann::json summary = nlohmann::json::parse(file(a, "summary.json").bytes);
    EXPECT_TRUE(summary["synthetic"].get<bool>());
    EXPECT_EQ(summary["comparisons"][0]["id"], "phase1-comprehension");
    EXPECT_EQ(summary["comparisons"][0]["pairs"].size(), 6u);
    EXPECT_EQ(summary["inputs"].size(), 24u);
}

TEST(Report, TablesCarryTheAnalysisNumbers) {
    std::vector<std::string> warnings;
    const std::vector<ParticipantResults> results = simulated(plantedEffect(study(), 4), warnings);
    const StudyAnalysis a = analyzeStudy(study(), results, {});
    const std::vector<ReportFile> files = report(results, warnings);
    const std::string& tests = file(files, "tests.csv").bytes;
    const KruskalWallisResult& kw = a.likert.kruskalWallis;
    EXPECT_NE(tests.find("phase2-likert,2,,kruskal-wallis,,," + std::to_string(kw.n) + ",," + significant6(kw.h) + ",3,,"),
              std::string::npos)
        << tests.substr(0, 600);
    const std::string& results_csv = file(files, "results.csv").bytes;
    EXPECT_NE(results_csv.find("phase1-comprehension,1,,proportion correct,point,24," +
                               significant6(a.comprehension.descriptives[0].mean) + ","),
              std::string::npos);
    // Every score of the overall comparisons is in scores.csv: 24 x 4 + 24 x 8 x 4 lines, and per verb.
    const std::string& scores = file(files, "scores.csv").bytes;
    EXPECT_EQ(std::count(scores.begin(), scores.end(), '\n') > 24 * 4 + 24 * 8 * 4, true);
}

TEST(Report, AnUndefinedTestIsWrittenAsEmptyNullOrDash) {
    // Only one participant, who saw each version: phase-1 per-verb cells with no question of
    // a verb in a version stay empty; SDs of one score are undefined.
    std::vector<std::string> warnings;
    std::vector<ParticipantResults> results = simulated(plantedEffect(study(), 4), warnings);
    results.resize(1);
    const std::vector<ReportFile> files = report(results, warnings);
    const nlohmann::json summary = nlohmann::json::parse(file(files, "summary.json").bytes);
    EXPECT_TRUE(summary["comparisons"][0]["versions"][0]["sd"].is_null());
    for (const ReportFile& f : files) {
        if (f.path.size() > 4 && f.path.substr(f.path.size() - 4) == ".png") continue;
        EXPECT_FALSE(hasNonFiniteWord(f.bytes)) << f.path;
    }
}

}  // namespace
