// ELAN files (stimuli/study/elan_export.hpp). ELAN's schema (EAFv3.0.xsd) is in no Debian or
// npm package, so the document is checked structurally: a real XML parser (xmllint, when
// installed) finds it well formed; every annotation's time slots exist and come in time order;
// every tier's linguistic type exists; annotations of a tier are in order, last a frame or
// more, do not overlap and lie on the clip's frame grid; the tiers hold what the timeline says.
#include "stimuli/study/elan_export.hpp"

#include "common/atomic_file.hpp"
#include "stimuli/story/timeline_builder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>

namespace signstim::stimuli {
namespace {

const std::string kSource = SIGNSTIM_SOURCE_DIR;

struct World {
    hand::HandModel model = hand::buildHandModel();
    HandshapeLibrary shapes = loadHandshapes(kSource + "/scenes/handshapes.json", model);
    VerbLibrary verbs = loadVerbLibrary(kSource + "/scenes/verbs.json");
    TrainedVerbModels models = loadVerbModels(kSource + "/scenes/models/verb_models.json", verbs);
    Lexicon lexicon = parseLexicon(parseJsonText(R"({
  "format": "signstim-lexicon", "version": 1,
  "locations": {"chest": [0, 0, 110]},
  "signs": [
    {"gloss": "MY", "hands": ["right"], "keyframes": {"right": [
      {"time": 0, "at": "chest", "offset": [0, 0, 60], "touch": "palm", "fingers": [-0.3, 1, 0], "palm": [0, 0, -1], "handshape": "B"},
      {"time": 0.25, "at": "chest", "touch": "palm", "fingers": [-0.3, 1, 0], "palm": [0, 0, -1], "handshape": "B"}]}}
  ]})", "test-lexicon.json"), shapes, model);
    // Synthetic: a fingerspelled name (JOHN, with J's hook), a verb, fs- with Z's strokes, a HOLD.
    Story story = parseStory(parseJsonText(R"json({
  "format": "signstim-story", "version": 1, "title": "T",
  "characters": [{"gloss": "JOHN", "position": 0.9}, {"gloss": "MARY", "position": -0.6}],
  "sentences": ["JOHN IX(0.9) MARY IX(-0.6)", "JOHN ASK MARY", "fs-JAZZ MY HOLD"],
  "questions": [{"question": "Q", "choices": ["a", "b", "c"], "answer": "A", "probes": {"sentence": 2, "verb": "ASK"}}]
})json", "test-story.json"), StoryVocabulary{&verbs, lexicon.glosses(), nullptr, nullptr});

    Timeline timeline(VerbVersion version) const {
        TimelineSources s;
        s.lexicon = &lexicon;
        s.shapes = &shapes;
        s.verbs = [this](const std::string& verb, VerbVersion v, double subject, double object, int, int) {
            return synthesizeVerb(VerbSources{&verbs, &models, kSource + "/scenes/animator"}, verb, v, subject, object);
        };
        return buildTimeline(story, version, s);
    }
};

const World& world() {
    static const World w;
    return w;
}

// XML's five entities back to text (the writer's escapeHtml uses these and &#39;).
std::string unescape(std::string text) {
    const std::pair<std::string, std::string> entities[] = {
        {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}};
    for (const auto& entity : entities)
        for (std::size_t at = text.find(entity.first); at != std::string::npos; at = text.find(entity.first, at + 1))
            text.replace(at, entity.first.size(), entity.second);
    return text;
}

struct ParsedAnnotation {
    std::string tier, id, value;
    long long start = 0, end = 0;
};

// The document's structure, checked as it is read (EXPECTs name what is wrong).
std::vector<ParsedAnnotation> checkStructure(const std::string& xml, double fps) {
    std::map<std::string, long long> slots;
    long long previous = -1;
    const std::regex slot(R"re(<TIME_SLOT TIME_SLOT_ID="([^"]+)" TIME_VALUE="(\d+)"/>)re");
    for (auto it = std::sregex_iterator(xml.begin(), xml.end(), slot); it != std::sregex_iterator(); ++it) {
        const long long ms = std::stoll((*it)[2]);
        EXPECT_TRUE(slots.emplace((*it)[1], ms).second) << "duplicate slot " << (*it)[1];
        EXPECT_GE(ms, previous) << "time slots out of order at " << (*it)[1];
        previous = ms;
        // On the frame grid: the start of some frame.
        EXPECT_EQ(ms, std::llround(std::llround(ms * fps / 1000.0) * 1000.0 / fps)) << ms;
    }
    std::set<std::string> types;
    const std::regex type(R"re(<LINGUISTIC_TYPE GRAPHIC_REFERENCES="false" LINGUISTIC_TYPE_ID="([^"]+)" TIME_ALIGNABLE="true"/>)re");
    for (auto it = std::sregex_iterator(xml.begin(), xml.end(), type); it != std::sregex_iterator(); ++it)
        types.insert((*it)[1]);
    std::vector<ParsedAnnotation> out;
    std::set<std::string> ids, tierIds;
    const std::regex tier(R"re(<TIER LINGUISTIC_TYPE_REF="([^"]+)" TIER_ID="([^"]+)"(/>|>([\s\S]*?)</TIER>))re");
    const std::regex annotation(
        R"re(<ALIGNABLE_ANNOTATION ANNOTATION_ID="([^"]+)" TIME_SLOT_REF1="([^"]+)" TIME_SLOT_REF2="([^"]+)">\s*<ANNOTATION_VALUE>([^<]*)</ANNOTATION_VALUE>)re");
    for (auto t = std::sregex_iterator(xml.begin(), xml.end(), tier); t != std::sregex_iterator(); ++t) {
        const std::string tierId = (*t)[2], body = (*t)[4];
        EXPECT_TRUE(types.count((*t)[1])) << "tier " << tierId << " has no linguistic type " << (*t)[1];
        EXPECT_TRUE(tierIds.insert(tierId).second) << "duplicate tier " << tierId;
        long long lastEnd = -1;
        for (auto a = std::sregex_iterator(body.begin(), body.end(), annotation); a != std::sregex_iterator(); ++a) {
            ParsedAnnotation p{tierId, (*a)[1], unescape((*a)[4])};
            EXPECT_TRUE(ids.insert(p.id).second) << "duplicate annotation id " << p.id;
            const auto r1 = slots.find((*a)[2]), r2 = slots.find((*a)[3]);
            EXPECT_TRUE(r1 != slots.end() && r2 != slots.end()) << p.id << " refers to a missing slot";
            if (r1 == slots.end() || r2 == slots.end()) continue;
            p.start = r1->second, p.end = r2->second;
            EXPECT_LT(p.start, p.end) << p.id;
            EXPECT_GE(p.start, lastEnd) << "overlap on " << tierId << " at " << p.id;
            lastEnd = p.end;
            out.push_back(p);
        }
    }
    EXPECT_EQ(xml.find("<ANNOTATION_DOCUMENT"), xml.find('\n') + 1);
    EXPECT_NE(xml.find("FORMAT=\"3.0\" VERSION=\"3.0\""), std::string::npos);
    return out;
}

std::vector<std::string> values(const std::vector<ParsedAnnotation>& all, const std::string& tier) {
    std::vector<std::string> v;
    for (const ParsedAnnotation& a : all)
        if (a.tier == tier) v.push_back(a.value);
    return v;
}

// xmllint --noout: a real XML parser's verdict (skipped without libxml2-utils).
void expectWellFormed(const std::string& xml) {
    if (std::system("command -v xmllint >/dev/null 2>&1") != 0) return;
    TemporaryFolder dir(std::filesystem::temp_directory_path() / "signstim-elan-test");
    const std::filesystem::path file = dir.path() / "clip.eaf";
    std::ofstream(file) << xml;
    EXPECT_EQ(std::system(("xmllint --noout '" + file.string() + "'").c_str()), 0) << xml;
}

TEST(ElanExport, OneClipHasEveryTierOnTheFrameGridWithWhatTheTimelineSigns) {
    const Timeline t = world().timeline(VerbVersion::Point);
    ElanDocumentOptions options;
    options.mediaUrl = "../clips/story-01_version-point.mp4";
    options.framesPerSecond = 30.0;
    options.sentenceGlosses = {"JOHN IX(0.9) MARY IX(-0.6)", "JOHN ASK MARY", "fs-JAZZ MY HOLD"};
    const std::string xml = elanDocument({{"", &t}}, options);
    expectWellFormed(xml);
    const auto all = checkStructure(xml, 30.0);
    EXPECT_NE(xml.find("RELATIVE_MEDIA_URL=\"../clips/story-01_version-point.mp4\""), std::string::npos);
    EXPECT_EQ(values(all, "sentences"), options.sentenceGlosses);
    std::vector<std::string> items;
    for (const TimelineSpan& s : t.spans)
        if (s.item >= 0 && s.kind != SpanKind::Rest) items.push_back(s.label);
    EXPECT_EQ(values(all, "signs"), items);
    EXPECT_EQ(values(all, "fingerspelling"), (std::vector<std::string>{"J", "O", "H", "N", "M", "A", "R", "Y", "J", "O", "H", "N", "M", "A", "R", "Y", "J", "A", "Z",
                                        "Z"}));
    EXPECT_EQ(values(all, "verb"), std::vector<std::string>{"ASK (point)"});
    // The non-manual tiers carry the timeline's marked spans (here the blinks at the sentence
    // ends: docs/nonmanuals.md), each once.
    std::vector<std::string> marked, written;
    for (const NonManualSpan& span : t.nonManualSpans) marked.push_back(span.text.empty() ? span.marker : span.marker + ": " + span.text);
    for (const ParsedAnnotation& a : all)
        if (a.tier.rfind("non-manual", 0) == 0) written.push_back(a.value);
    std::sort(marked.begin(), marked.end());
    std::sort(written.begin(), written.end());
    EXPECT_FALSE(marked.empty()) << "a story of three sentences blinks at its sentence boundaries";
    EXPECT_EQ(written, marked);
    // The letters lie within their words' signs, in order.
    long long fsStart = 0, fsEnd = 0;
    for (const ParsedAnnotation& a : all)
        if (a.tier == "signs" && a.value == "fs-JAZZ") fsStart = a.start, fsEnd = a.end;
    int inside = 0;
    for (const ParsedAnnotation& a : all)
        if (a.tier == "fingerspelling" && a.start >= fsStart && a.end <= fsEnd) ++inside;
    EXPECT_EQ(inside, 4);
}

TEST(ElanExport, SpelledLettersFollowTheKeysOfJAndZ) {
    const Timeline t = world().timeline(VerbVersion::Point);
    for (const TimelineSpan& span : t.spans) {
        if (span.label != "fs-JAZZ") continue;
        const std::vector<SpelledLetter> letters = spelledLetters(t, span);
        ASSERT_EQ(letters.size(), 4u);
        for (std::size_t i = 0; i < letters.size(); ++i) {
            EXPECT_LT(letters[i].startSeconds, letters[i].endSeconds);
            if (i > 0) {
                EXPECT_LT(letters[i - 1].endSeconds, letters[i].startSeconds) << "a transition between letters";
            }
        }
        EXPECT_NEAR(letters.front().startSeconds, span.keysStartSeconds, 1e-9);
        EXPECT_NEAR(letters.back().endSeconds, span.keysEndSeconds, 1e-9);
        // J's hook and Z's strokes take longer than A's hold.
        const double a = letters[1].endSeconds - letters[1].startSeconds;
        EXPECT_GT(letters[0].endSeconds - letters[0].startSeconds, a);
        EXPECT_GT(letters[2].endSeconds - letters[2].startSeconds, a);
        return;
    }
    FAIL() << "no fs-JAZZ span";
}

TEST(ElanExport, SideBySidePanelsGetAVerbTierEachAndNonManualsAreLayeredAndEscaped) {
    const Timeline point = world().timeline(VerbVersion::Point), vector = world().timeline(VerbVersion::Vector);
    Timeline marked = point;  // hand-built non-manual spans (the face work is not in yet)
    marked.nonManualSpans = {{"topic", 0.2, 1.0, 0, 1.0, ""},
                             {"blink", 0.5, 0.7, 0, 1.0, ""},  // during the topic: a second tier
                             {"mouthing", 1.2, 1.6, 0, 1.0, "<ask> & \"tell\""}};
    ElanDocumentOptions options;
    options.mediaUrl = "../clips/likert-01_panels-PV.mp4";
    options.framesPerSecond = 30000.0 / 1001.0;
    const std::string xml = elanDocument({{"A", &marked}, {"B", &vector}}, options);
    expectWellFormed(xml);
    const auto all = checkStructure(xml, options.framesPerSecond);
    EXPECT_EQ(values(all, "verb A"), std::vector<std::string>{"ASK (point)"});
    EXPECT_EQ(values(all, "verb B"), std::vector<std::string>{"ASK (vector)"});
    EXPECT_EQ(values(all, "non-manual"), (std::vector<std::string>{"topic", "mouthing: <ask> & \"tell\""}));
    EXPECT_EQ(values(all, "non-manual 2"), std::vector<std::string>{"blink"});
    EXPECT_NE(xml.find("mouthing: &lt;ask&gt; &amp; &quot;tell&quot;"), std::string::npos);
    EXPECT_EQ(xml.find("TIER_ID=\"verb\""), std::string::npos) << "panels' verb tiers are named by panel";
    // Both verb annotations cover the same slot (the same length in every version).
    long long a = -1, b = -2;
    for (const ParsedAnnotation& x : all) {
        if (x.tier == "verb A") a = x.start;
        if (x.tier == "verb B") b = x.start;
    }
    EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace signstim::stimuli
