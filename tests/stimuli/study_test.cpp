// The study file and the plan drawn from it (stimuli/study/study.hpp): names as SPEC §5, every
// participant's schedule in the listing, the design hash, and the listing's JSON round trip
// (what `study merge` and `verify` read back).
#include "stimuli/json_source.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/study/study.hpp"

#include <gtest/gtest.h>

#include <map>

using namespace signstim::stimuli;

namespace {

StudyFile parse(const std::string& text) { return parseStudyFile(parseJsonText(text, "study.json")); }

const std::string kStudy = R"({
  "format": "signstim-study", "version": 1, "title": "T", "seed": 3, "participants": 8,
  "versions": ["point", "vector", "animator", "uninflected"],
  "stories": ["a.json", "b.json", "c.json", "d.json", "e.json", "f.json", "g.json", "h.json"],
  "phase2": {"story": "s.json", "sentences": [2, 1, 3, 4]},
  "render": {"size": "640x480", "fps": "30000/1001", "msaa": 4, "rate": 1.25}
})";

std::vector<Story> fakeStories(std::size_t n) {
    std::vector<Story> stories(n);
    for (std::size_t i = 0; i < n; ++i) {
        stories[i].title = "Story " + std::to_string(i + 1) + ", with \"quotes\"";
        stories[i].sentences.push_back({"JOHN IX(0.9) ASK MARY IX(-0.6)", {}, 1});
        stories[i].questions.push_back({"Who asked?", {"John", "Mary", "Nobody"}, 0, 0, "ASK", 1});
    }
    return stories;
}

Story fakeSentences() {
    Story s;
    for (const char* verb : {"ASK", "GIVE", "SEND", "TELL"}) {
        StorySentence sentence;
        sentence.gloss = std::string("JOHN IX(0.9) ") + verb + " MARY IX(-0.6)";
        StoryItem item;
        item.kind = StoryItemKind::Verb;
        item.gloss = verb;
        sentence.items.push_back(item);
        s.sentences.push_back(sentence);
    }
    return s;
}

}  // namespace

TEST(StudyFile, ReadsEveryFieldWithItsDefaults) {
    const StudyFile study = parse(kStudy);
    EXPECT_EQ(study.seed, 3u);
    EXPECT_EQ(study.participants, 8u);
    ASSERT_EQ(study.stories.size(), 8u);
    EXPECT_EQ(study.stories[1].written, "b.json");
    EXPECT_EQ(study.phase2Sentences, (std::vector<int>{1, 0, 2, 3}));
    EXPECT_EQ(study.render.width, 640u);
    EXPECT_EQ(study.render.fps, "30000/1001");
    EXPECT_DOUBLE_EQ(study.render.rate, 1.25);
    EXPECT_EQ(study.quick.width, 320u);  // default quick settings
    EXPECT_EQ(study.quick.msaa, 1u);
    EXPECT_EQ(study.likertMinimum, 1);
    EXPECT_EQ(study.likertMaximum, 10);
    EXPECT_EQ(study.experiment, "");  // not said: the command line (or an earlier run) decides
}

TEST(StudyFile, OutputsNameTheJsPsychExperimentOrNone) {
    const auto withOutputs = [](const std::string& outputs) {
        std::string text = kStudy;
        text.replace(text.rfind('}'), 1, ", \"outputs\": " + outputs + "}");
        return parse(text);
    };
    EXPECT_EQ(withOutputs(R"({"experiment": "jspsych"})").experiment, "jspsych");
    EXPECT_EQ(withOutputs(R"({"experiment": "none", "pngFrames": true})").experiment, "none");
    EXPECT_TRUE(withOutputs(R"({"experiment": "none", "pngFrames": true})").pngFrames);
    for (const std::string bad : {R"({"experiment": "psychopy"})", R"({"experiment": true})", R"({"experiment": ""})"}) {
        try {
            withOutputs(bad);
            ADD_FAILURE() << "accepted: " << bad;
        } catch (const signstim::InputError& e) {
            EXPECT_EQ(e.field(), "/outputs/experiment") << e.what();
            EXPECT_NE(std::string(e.what()).find("jspsych"), std::string::npos) << e.what();
        }
    }
}

TEST(StudyFile, MistakesNameTheLineAndTheField) {
    const auto expectError = [](std::string text, const std::string& from, const std::string& to, const std::string& field) {
        text.replace(text.find(from), from.size(), to);
        try {
            parse(text);
            ADD_FAILURE() << "accepted: " << to;
        } catch (const signstim::InputError& e) {
            EXPECT_EQ(e.field(), field) << e.what();
            EXPECT_GT(e.line(), 0) << e.what();
        }
    };
    expectError(kStudy, "\"seed\": 3", "\"seed\": -3", "/seed");
    expectError(kStudy, "\"seed\": 3", "\"seed\": 3.5", "/seed");
    expectError(kStudy, "\"participants\": 8", "\"participants\": 100000", "/participants");
    expectError(kStudy, "\"msaa\": 4", "\"msaa\": 2", "/render/msaa");
    expectError(kStudy, "\"rate\": 1.25", "\"rate\": 9", "/render/rate");
    expectError(kStudy, "\"640x480\"", "\"640x481\"", "/render/size");
    expectError(kStudy, "\"c.json\"", "\"a.json\"", "/stories/2");               // listed twice
    expectError(kStudy, "\"vector\"", "\"point\"", "/versions/1");              // listed twice
    expectError(kStudy, ", \"h.json\"]", "]", "/stories");                      // 7 stories over 4 versions
    expectError(kStudy, "[2, 1, 3, 4]", "[2, 2, 3, 4]", "/phase2/sentences/1");  // listed twice
}

TEST(StudyPlan, EveryParticipantSeesEveryStoryOnceAndEachVersionEquallyOften) {
    const StudyFile study = parse(kStudy);
    const std::vector<Story> stories = fakeStories(8);
    const Story sentences = fakeSentences();
    const StudyListing listing = planStudy(study, stories, &sentences, "1.2.3", false);
    ASSERT_EQ(listing.participants.size(), 8u);
    EXPECT_EQ(listing.participants[0].id, "P01");
    EXPECT_EQ(listing.stories[2].clips[0].video, "clips/story-03_version-point.mp4");
    EXPECT_EQ(listing.stories[2].clips[3].poster, "posters/story-03_version-uninflected.png");
    EXPECT_TRUE(listing.stories[2].clips[3].frames.empty());
    for (const ListedParticipant& p : listing.participants) {
        std::map<std::size_t, int> storyCount, versionCount;
        for (const ListedPhase1Trial& t : p.phase1) {
            ++storyCount[t.story];
            ++versionCount[t.version];
        }
        EXPECT_EQ(storyCount.size(), 8u) << p.id;
        for (const auto& [v, n] : versionCount) EXPECT_EQ(n, 2) << p.id << " version " << v;
        ASSERT_EQ(p.phase2.size(), 4u);
        for (std::size_t t = 0; t < p.phase2.size(); ++t) EXPECT_EQ(p.phase2[t].trial, t + 1);
    }
    // Phase 2: sentence i of the listing is sentence phase2Sentences[i] of the file, with its verb and panel code.
    EXPECT_EQ(listing.sentences[0].verb, "GIVE");
    EXPECT_EQ(listing.sentences[0].id, "likert-01");
    EXPECT_EQ(listing.sentences[0].panelCode.size(), 4u);
    EXPECT_EQ(listing.sentences[0].clip.video, "clips/likert-01_panels-" + listing.sentences[0].panelCode + ".mp4");
}

TEST(StudyPlan, DesignHashFollowsTheDesignNotTheRenderSettings) {
    const std::vector<Story> stories = fakeStories(8);
    const Story sentences = fakeSentences();
    const StudyListing a = planStudy(parse(kStudy), stories, &sentences, "1", false);
    std::string otherSize = kStudy;
    otherSize.replace(otherSize.find("640x480"), 7, "320x240");
    EXPECT_EQ(planStudy(parse(otherSize), stories, &sentences, "1", false).designHash, a.designHash);
    std::string otherSeed = kStudy;
    otherSeed.replace(otherSeed.find("\"seed\": 3"), 9, "\"seed\": 4");
    EXPECT_NE(planStudy(parse(otherSeed), stories, &sentences, "1", false).designHash, a.designHash);
    EXPECT_EQ(a.designHash.size(), 64u);
}

TEST(StudyPlan, DesignHashReadsWhatTheStoriesSayNotWhereTheyLive) {
    std::vector<Story> stories = fakeStories(8);
    const Story sentences = fakeSentences();
    const StudyListing a = planStudy(parse(kStudy), stories, &sentences, "1", false);
    StudyFile moved = parse(kStudy);
    for (StudyFile::StoryEntry& entry : moved.stories) {
        entry.written = "renamed-stories/" + entry.path.filename().string();
        entry.path = std::filesystem::path("/elsewhere") / entry.written;
    }
    const StudyListing b = planStudy(moved, stories, &sentences, "1", false);
    EXPECT_NE(b.stories.front().file, a.stories.front().file);
    EXPECT_EQ(b.designHash, a.designHash);
    stories[2].sentences[0].gloss += " AGAIN";
    EXPECT_NE(planStudy(parse(kStudy), stories, &sentences, "1", false).designHash, a.designHash);
}

TEST(StudyPlan, ListingRoundTripsThroughJson) {
    const std::vector<Story> stories = fakeStories(8);
    const Story sentences = fakeSentences();
    StudyListing listing = planStudy(parse(kStudy), stories, &sentences, "1", true);
    listing.stories[1].clips[2].durationSeconds = 12.5;
    listing.stories[1].clips[2].frameCount = 376;
    const nlohmann::json json = listingToJson(listing);
    const StudyListing back = listingFromJson(json, "plan.json");
    EXPECT_EQ(listingToJson(back), json);
    EXPECT_EQ(back.stories[1].clips[2].frameCount, 376u);
    EXPECT_EQ(designText(back), designText(listing));
    // A damaged plan is refused naming the field.
    nlohmann::json damaged = json;
    damaged["participants"][0]["phase1"][0]["version"] = 9;
    try {
        listingFromJson(damaged, "plan.json");
        ADD_FAILURE() << "accepted version 9 of 4";
    } catch (const signstim::InputError& e) {
        EXPECT_EQ(e.field(), "/participants/0/phase1/0/version");
    }
}

// ---- issue 24: "order" and "session" ---------------------------------------------------------

std::string withField(const std::string& field) {
    std::string text = kStudy;
    text.replace(text.rfind('}'), 1, ", " + field + "}");
    return text;
}

TEST(StudyFile, OrderIsRandomByDefaultOrBalanced) {
    EXPECT_EQ(parse(kStudy).order, StoryOrder::Random);
    EXPECT_EQ(parse(kStudy).designSpec().order, StoryOrder::Random);
    EXPECT_EQ(parse(withField(R"("order": "random")")).order, StoryOrder::Random);
    const StudyFile balanced = parse(withField(R"("order": "balanced")"));
    EXPECT_EQ(balanced.order, StoryOrder::Balanced);
    EXPECT_EQ(balanced.designSpec().order, StoryOrder::Balanced);
    for (const std::string bad : {R"("order": "williams")", R"("order": 1)", R"("order": "")"}) {
        try {
            parse(withField(bad));
            ADD_FAILURE() << "accepted: " << bad;
        } catch (const signstim::InputError& e) {
            EXPECT_EQ(e.field(), "/order") << e.what();
            EXPECT_NE(std::string(e.what()).find("balanced"), std::string::npos) << e.what();
        }
    }
}

TEST(StudyFile, SessionSetsThePromptAndTheBackgroundQuestions) {
    const StudyFile plain = parse(kStudy);
    EXPECT_EQ(plain.ratingPrompt, kDefaultRatingPrompt);
    EXPECT_NE(plain.ratingPrompt.find("quality of the verb"), std::string::npos) << "the paper's question";
    EXPECT_EQ(plain.background, (std::vector<std::string>{"hearing", "aslAge", "aslSchool", "dailyUse"}));
    const StudyFile set = parse(withField(R"("session": {"ratingPrompt": "Rate {verb}", "background": ["dailyUse", "hearing"]})"));
    EXPECT_EQ(set.ratingPrompt, "Rate {verb}");
    EXPECT_EQ(set.background, (std::vector<std::string>{"dailyUse", "hearing"}));
    EXPECT_TRUE(parse(withField(R"("session": {"background": []})")).background.empty());
    const std::vector<std::pair<std::string, std::string>> bad = {
        {R"("session": {"background": ["age"]})", "/session/background/0"},
        {R"("session": {"background": ["hearing", "hearing"]})", "/session/background/1"},
        {R"("session": {"background": "hearing"})", "/session/background"},
        {R"("session": {"ratingPrompt": ""})", "/session/ratingPrompt"},
        {R"("session": {"prompt": "x"})", "/session/prompt"},
        {R"("session": true)", "/session"}};
    for (const auto& [text, field] : bad) {
        try {
            parse(withField(text));
            ADD_FAILURE() << "accepted: " << text;
        } catch (const signstim::InputError& e) {
            EXPECT_EQ(e.field(), field) << e.what();
        }
    }
}

TEST(StudyPlan, TheSessionTravelsWithTheListingAndOldPlansGetTheDefaults) {
    const std::vector<Story> stories = fakeStories(8);
    const Story sentences = fakeSentences();
    const StudyListing listing = planStudy(
        parse(withField(R"("session": {"ratingPrompt": "Rate {verb}", "background": ["aslAge"]})")), stories,
        &sentences, "1", false);
    EXPECT_EQ(listing.ratingPrompt, "Rate {verb}");
    EXPECT_EQ(listing.background, (std::vector<std::string>{"aslAge"}));
    nlohmann::json json = listingToJson(listing);
    EXPECT_EQ(listingFromJson(json, "plan.json").ratingPrompt, "Rate {verb}");
    EXPECT_EQ(listingFromJson(json, "plan.json").background, listing.background);
    json.erase("ratingPrompt");
    json.erase("background");
    const StudyListing old = listingFromJson(json, "plan.json");  // a plan written before issue 24
    EXPECT_EQ(old.ratingPrompt, kDefaultRatingPrompt);
    EXPECT_EQ(old.background.size(), kBackgroundQuestions.size());
}

TEST(StudyPlan, BalancedOrderChangesTheSchedulesAndTheDesignHashButNotTheGroups) {
    const std::vector<Story> stories = fakeStories(8);
    const Story sentences = fakeSentences();
    const StudyListing random = planStudy(parse(kStudy), stories, &sentences, "1", false);
    const StudyListing balanced = planStudy(parse(withField(R"("order": "balanced")")), stories, &sentences, "1", false);
    EXPECT_NE(random.designHash, balanced.designHash);
    ASSERT_EQ(random.participants.size(), balanced.participants.size());
    for (std::size_t p = 0; p < random.participants.size(); ++p)
        EXPECT_EQ(random.participants[p].group, balanced.participants[p].group);
    // 8 participants = two blocks of the 4 Williams rows: each version twice at each position.
    std::map<std::pair<std::size_t, std::size_t>, int> count;
    for (const ListedParticipant& p : balanced.participants)
        for (std::size_t i = 0; i < p.phase1.size(); ++i) ++count[{i, p.phase1[i].version}];
    for (std::size_t i = 0; i < 8; ++i)
        for (std::size_t v = 0; v < 4; ++v) EXPECT_EQ((count[{i, v}]), 2) << "position " << i << " version " << v;
}

TEST(StudyNames, ParticipantIdsArePaddedToTheCount) {
    EXPECT_EQ(participantId(0, 24), "P01");
    EXPECT_EQ(participantId(99, 100), "P100");
    EXPECT_EQ(participantId(4, 100), "P005");
    EXPECT_EQ(storyClipName(2, VerbVersion::Animator), "story-03_version-animator");
    EXPECT_EQ(likertClipName(4, "VPAU"), "likert-05_panels-VPAU");
}
