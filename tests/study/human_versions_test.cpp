// Human-video versions in the study file (stimuli/study/human_versions.hpp, issue 24 §2): the
// "humanVersions" field and its refusals, the path patterns, and the design they make — a
// human version counts as a version in the phases the study puts it in (5-version designs,
// SPEC §4.4), phase 2 only where the study says. No clips are read here (app tests do that).
#include "stimuli/json_source.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/study/study.hpp"
#include "stimuli/study/review_page.hpp"
#include "stimuli/study/study_exports.hpp"

#include "common/error.hpp"

#include <gtest/gtest.h>

#include <map>
#include <set>

using namespace signstim::stimuli;

namespace {

StudyFile parse(const std::string& text) { return parseStudyFile(parseJsonText(text, "study.json")); }

// A study of `stories` stories with the four animated versions and `human` as its humanVersions.
std::string studyText(std::size_t stories, const std::string& human, std::size_t sentences = 4, std::size_t participants = 10) {
    std::string list, numbers;
    for (std::size_t i = 0; i < stories; ++i) list += (i ? ", \"" : "\"") + std::string("s") + std::to_string(i) + ".json\"";
    for (std::size_t i = 0; i < sentences; ++i) numbers += (i ? ", " : "") + std::to_string(i + 1);
    return R"({"format": "signstim-study", "version": 1, "title": "T", "seed": 7, "participants": )" +
           std::to_string(participants) + R"(, "versions": ["point", "vector", "animator", "uninflected"], "stories": [)" +
           list + R"(], "phase2": {"story": "p2.json", "sentences": [)" + numbers + R"(]}, "render": {"size": "64x64"},
           "humanVersions": )" + human + "}";
}

// The message of the InputError parsing `text` throws ("" when it parses).
std::string refusal(const std::string& text) {
    try {
        parse(text);
    } catch (const signstim::InputError& e) {
        return e.field() + ": " + e.detail();
    }
    return "";
}

std::vector<Story> fakeStories(std::size_t n) {
    std::vector<Story> stories(n);
    for (std::size_t i = 0; i < n; ++i) {
        stories[i].title = "Story " + std::to_string(i + 1);
        stories[i].sentences.push_back({"JOHN IX(0.9) ASK MARY IX(-0.6)", {}, 1});
        stories[i].questions.push_back({"Who asked?", {"John", "Mary", "Nobody"}, 0, 0, "ASK", 1});
    }
    return stories;
}

Story fakeSentences(std::size_t n) {
    Story s;
    for (std::size_t i = 0; i < n; ++i) {
        StorySentence sentence;
        sentence.gloss = "JOHN IX(0.9) ASK MARY IX(-0.6) " + std::to_string(i);
        StoryItem item;
        item.kind = StoryItemKind::Verb;
        item.gloss = "ASK";
        sentence.items.push_back(item);
        s.sentences.push_back(sentence);
    }
    return s;
}

const std::string kBoth =
    R"([{"name": "human", "phase1Clips": "human/{story}.mp4", "phase2Clips": "human/{sentence}.mp4"}])";
const std::string kPhase1Only = R"([{"name": "human", "phase1Clips": "recordings/{storyFile}-signer1.mp4"}])";

}  // namespace

TEST(HumanVersions, AreReadWithTheirPatternsAndLetters) {
    const StudyFile study = parse(studyText(10, kBoth, 5));
    ASSERT_EQ(study.humanVersions.size(), 1u);
    EXPECT_EQ(study.humanVersions[0].name, "human");
    EXPECT_EQ(study.humanVersions[0].letter, "H");
    EXPECT_EQ(study.humanVersions[0].phase1Clips, "human/{story}.mp4");
    EXPECT_EQ(study.humanVersions[0].phase2Clips, "human/{sentence}.mp4");
    // Relative to the study file's folder; {story} is the study's id, {storyFile} the story file's stem.
    EXPECT_EQ(humanStoryClip(study, study.humanVersions[0], 2), "human/story-03.mp4");
    EXPECT_EQ(humanSentenceClip(study, study.humanVersions[0], 4), "human/likert-05.mp4");
    const StudyFile other = parse(studyText(10, kPhase1Only));
    EXPECT_EQ(humanStoryClip(other, other.humanVersions[0], 2), "recordings/s2-signer1.mp4");
    EXPECT_EQ(expandHumanPattern("a/{sentenceNumber}/{x}", {{"sentenceNumber", "07"}}), "a/07/{x}");
}

TEST(HumanVersions, MistakesAreRefusedNamingTheField) {
    EXPECT_NE(refusal(studyText(10, R"([{"name": "point", "phase1Clips": "h/{story}.mp4"}])")).find("/humanVersions/0/name"), std::string::npos);
    EXPECT_NE(refusal(studyText(10, R"([{"name": "Human!", "phase1Clips": "h/{story}.mp4"}])")).find("lowercase"), std::string::npos);
    // A pattern without a placeholder would name one file for every story.
    EXPECT_NE(refusal(studyText(10, R"([{"name": "human", "phase1Clips": "h/all.mp4"}])")).find("one file for every story"), std::string::npos);
    EXPECT_NE(refusal(studyText(10, R"([{"name": "human", "phase1Clips": "h/{sentence}.mp4"}])")).find("unknown placeholder {sentence}"), std::string::npos);
    EXPECT_NE(refusal(studyText(10, R"([{"name": "human", "phase1Clips": "h/{story.mp4"}])")).find("without its '}'"), std::string::npos);
    EXPECT_NE(refusal(studyText(10, R"([{"name": "human"}])")).find("phase1Clips\" and/or"), std::string::npos);
    EXPECT_NE(refusal(studyText(10, R"([{"name": "human", "phase1Clips": "h/{story}.mp4", "clips": "x"}])")).find("unknown field 'clips'"), std::string::npos);
    // "point" takes P; a human version named "pat" needs its own letter.
    EXPECT_NE(refusal(studyText(10, R"([{"name": "pat", "phase1Clips": "h/{story}.mp4"}])")).find("/humanVersions/0/name: the letter P"), std::string::npos);
    EXPECT_EQ(refusal(studyText(10, R"([{"name": "pat", "letter": "T", "phase1Clips": "h/{story}.mp4"}])")), "");
    // Five phase-1 versions need a multiple of five stories, and say the human version counts.
    const std::string notFive = refusal(studyText(12, kPhase1Only));
    EXPECT_NE(notFive.find("12 stories cannot be split evenly over 5 versions"), std::string::npos) << notFive;
    EXPECT_NE(notFive.find("human versions in phase 1 count"), std::string::npos) << notFive;
}

// SPEC §4.4 with a fifth version: every schedule shows every version equally often, the groups
// cover every story x version cell once, phase-2 panels are balanced over the versions phase 2 shows.
TEST(HumanVersions, FiveVersionDesignsAreBalancedInThePhasesTheStudyNames) {
    for (const std::string& human : {kBoth, kPhase1Only}) {
        const bool inPhase2 = human == kBoth;
        const StudyFile study = parse(studyText(10, human, inPhase2 ? 5 : 4, 20));
        const StudyDesignSpec spec = study.designSpec();
        ASSERT_EQ(spec.versions, 5u);
        ASSERT_EQ(spec.phase2Versions(), inPhase2 ? 5u : 4u);
        const Story sentences = fakeSentences(inPhase2 ? 5 : 4);
        const StudyListing listing = planStudy(study, fakeStories(10), &sentences, "test", false);
        EXPECT_EQ(listing.versions, (std::vector<std::string>{"point", "vector", "animator", "uninflected", "human"}));
        EXPECT_EQ(listing.versionLetters.back(), "H");
        EXPECT_EQ(listing.stories[3].clips[4].video, "clips/story-04_version-human.mp4");
        std::set<std::pair<std::size_t, std::size_t>> cells;
        for (std::size_t s = 0; s < 10; ++s)
            for (std::size_t g = 0; g < 5; ++g) cells.insert({s, listing.groupVersion[s][g]});
        EXPECT_EQ(cells.size(), 50u);  // every story in every version, once over the groups
        for (const ListedParticipant& p : listing.participants) {
            std::map<std::size_t, int> seen;
            for (const ListedPhase1Trial& t : p.phase1) ++seen[t.version];
            EXPECT_EQ(seen.size(), 5u);
            for (const auto& entry : seen) EXPECT_EQ(entry.second, 2) << p.id;
        }
        // Panels: each phase-2 version in each panel equally often; the human version only where the study says.
        const std::size_t panels = likertPanelCount(listing);
        std::map<std::pair<std::size_t, std::size_t>, int> panelCount;
        bool humanShown = false;
        for (const ListedSentence& sentence : listing.sentences) {
            ASSERT_EQ(sentence.panelVersion.size(), panels);
            for (std::size_t k = 0; k < panels; ++k) ++panelCount[{k, sentence.panelVersion[k]}];
            humanShown = humanShown || sentence.panelCode.find('H') != std::string::npos;
        }
        EXPECT_EQ(panelCount.size(), panels * panels);
        for (const auto& entry : panelCount) EXPECT_EQ(entry.second, 1);
        EXPECT_EQ(humanShown, inPhase2);
        // The exports accept the listing (a phase-1-only version leaves phase 2 with fewer panels).
        const std::string csv = conditionsCsv(listing, 0);
        EXPECT_NE(csv.find("panel_d_version"), std::string::npos);
        EXPECT_EQ(csv.find("panel_e_version") != std::string::npos, inPhase2);
        EXPECT_NO_THROW(gorillaSpreadsheetCsv(listing, 0));
        EXPECT_NO_THROW(likertResponseSheetHtml(listing, 0));
    }
}

// A human version in phase 2 only: phase 1 is the animated versions' design (4 groups, a story's
// clips are theirs alone), phase 2 shows all five in every panel equally often, and every writer
// of the listing accepts it.
TEST(HumanVersions, APhase2OnlyVersionLeavesPhase1ToTheOthersAndJoinsEveryPanel) {
    const StudyFile study = parse(studyText(8, R"([{"name": "human", "phase2Clips": "h/{sentence}.mp4"}])", 5, 8));
    const StudyDesignSpec spec = study.designSpec();
    ASSERT_EQ(spec.versions, 4u);
    ASSERT_EQ(spec.phase2Versions(), 5u);
    const Story sentences = fakeSentences(5);
    const StudyListing listing = planStudy(study, fakeStories(8), &sentences, "test", false);
    EXPECT_EQ(listing.versions, (std::vector<std::string>{"point", "vector", "animator", "uninflected", "human"}));
    for (const ListedStory& story : listing.stories) {
        ASSERT_EQ(story.clips.size(), 4u) << story.id;
        for (const ListedClip& clip : story.clips) EXPECT_EQ(clip.video.find("human"), std::string::npos);
    }
    for (const std::vector<std::size_t>& row : listing.groupVersion) EXPECT_EQ(row.size(), 4u);
    for (const ListedParticipant& p : listing.participants)
        for (const ListedPhase1Trial& t : p.phase1) EXPECT_LT(t.version, 4u) << p.id;
    std::map<std::pair<std::size_t, std::size_t>, int> panelCount;
    for (const ListedSentence& sentence : listing.sentences) {
        ASSERT_EQ(sentence.panelVersion.size(), 5u);
        for (std::size_t k = 0; k < 5; ++k) ++panelCount[{k, sentence.panelVersion[k]}];
    }
    EXPECT_EQ(panelCount.size(), 25u);  // every version in every panel, once over the 5 sentences
    const std::string csv = conditionsCsv(listing, 0);
    EXPECT_NE(csv.find("panel_e_version"), std::string::npos);
    EXPECT_NE(overviewCsv(listing).find("story,title,group_1,group_2,group_3,group_4\r\n"), std::string::npos);
    EXPECT_NO_THROW(gorillaSpreadsheetCsv(listing, 0));
    EXPECT_NO_THROW(jspsychTimelineVariables(listing, 0));
    EXPECT_NO_THROW(likertResponseSheetHtml(listing, 0));
    EXPECT_NO_THROW(questionSheetHtml(listing));
    EXPECT_NE(reviewPageHtml(listing).find("likert-01"), std::string::npos);
    // The study folder's plan (what resume, verify and merge read back) holds it unchanged.
    EXPECT_EQ(listingToJson(listingFromJson(listingToJson(listing), "plan.json")), listingToJson(listing));
}

// Adding a human version changes the design (and its hash); its recordings' paths do not.
TEST(HumanVersions, TheDesignHashNamesTheVersionsNotWhereTheRecordingsLive) {
    const Story sentences = fakeSentences(5);
    const auto hash = [&](const std::string& human) {
        return planStudy(parse(studyText(10, human, 5)), fakeStories(10), &sentences, "test", false).designHash;
    };
    const std::string moved = R"([{"name": "human", "phase1Clips": "elsewhere/{story}.mov", "phase2Clips": "x/{sentenceNumber}.mp4"}])";
    EXPECT_EQ(hash(kBoth), hash(moved));
    EXPECT_NE(hash(kBoth), hash(R"([{"name": "deaf-signer", "letter": "H", "phase1Clips": "h/{story}.mp4", "phase2Clips": "h/{sentence}.mp4"}])"));
}
