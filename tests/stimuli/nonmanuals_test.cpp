// Non-manual markers (issue 23 §4-§6, docs/nonmanuals.md, SPEC §6.4): the gloss syntax and its
// errors at line:column, the channels and spans the timeline builder makes (onsets before the
// manual span, ramps, the held last sign of a y/n question, blinks at boundaries and between),
// their identity across the four versions, the `nonManuals` switch and `story --json`.
#include "stimuli/story/gloss.hpp"
#include "stimuli/story/gloss_markers.hpp"
#include "stimuli/story/nonmanuals.hpp"
#include "stimuli/story/story_world.hpp"
#include "stimuli/story/timeline_builder.hpp"
#include "stimuli/study/study.hpp"
#include "stimuli/verbs/signing_space.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <string>

namespace signstim::stimuli {
namespace {

const std::string kScenes = std::string(SIGNSTIM_SOURCE_DIR) + "/scenes";
const std::array<VerbVersion, 4> kVersions{VerbVersion::Point, VerbVersion::Vector, VerbVersion::Animator,
                                           VerbVersion::Uninflected};

const StoryWorld& world() {
    static const StoryWorld w(kScenes, "");
    return w;
}

// A story of these sentences (each a JSON string on its own line 4, 5, ...) with JOHN at 0.9
// and MARY at -0.6.
Story storyFromText(const std::string& sentences, const std::string& extra = "") {
    const std::string text = "{\"format\": \"signstim-story\", \"version\": 1, \"title\": \"T\",\n"
                             "  \"characters\": [{\"gloss\": \"JOHN\", \"position\": 0.9}, {\"gloss\": \"MARY\", \"position\": -0.6}],\n"
                             "  \"sentences\": [\n" + sentences + "]" + extra + "}";
    return parseStory(parseJsonText(text, "nm.json"), world().vocabulary());
}

Timeline build(const Story& story, VerbVersion v = VerbVersion::Point, double rate = 1.0, bool nonManuals = true) {
    StoryTiming timing = story.timing;
    if (!timing.given()) timing.preset = "natural";
    TimelineOptions options = timelineOptionsFor(timing, rate);
    options.nonManuals = nonManuals;
    return buildTimeline(story, v, world().sources(story), options);
}

std::string storyFile(int n) {
    char name[64];
    std::snprintf(name, sizeof name, "/stories/story-%02d.json", n);
    return kScenes + name;
}

const NonManualSpan* findSpan(const Timeline& t, const std::string& marker) {
    for (const NonManualSpan& s : t.nonManualSpans)
        if (s.marker == marker) return &s;
    return nullptr;
}

double value(const Timeline& t, const std::string& channel, double time) {
    const NonManualTrack* track = findNonManual(t, channel);
    return track ? sampleNonManual(*track, time) : 0.0;
}

// The manual span of items [first, last] of a sentence: its first keys to its last.
std::pair<double, double> manual(const Timeline& t, int sentence, int first, int last) {
    double start = 1e9, end = -1e9;
    for (const TimelineSpan& s : t.spans)
        if (s.sentence == sentence && s.item >= first && s.item <= last) {
            start = std::min(start, s.keysStartSeconds);
            end = std::max(end, s.keysEndSeconds);
        }
    return {start, end};
}

// ---- grammar ------------------------------------------------------------------------------

TEST(NonManualGloss, EveryMarkerIsReadOverTheSignsItBrackets) {
    for (const MarkerDefinition& d : markerDefinitions()) {
        const std::string w(d.written);
        if (d.markerClass == MarkerClass::Event) {
            const GlossParse p = parseGloss("KNOW [" + w + "] GO");
            ASSERT_FALSE(p.error) << w << ": " << p.error->message;
            ASSERT_EQ(p.markers.size(), 1u) << w;
            EXPECT_EQ(p.markers[0].name, d.name);
            EXPECT_TRUE(p.markers[0].event());
            EXPECT_EQ(p.markers[0].firstItem, 1);
            continue;
        }
        const std::string head = d.argument == MarkerArgument::Character ? w + "(JOHN)"
                                 : d.argument == MarkerArgument::Word    ? w + "(know)"
                                                                         : w;
        const GlossParse p = parseGloss("JOHN [" + head + " NOT KNOW] GO");
        ASSERT_FALSE(p.error) << w << ": " << p.error->message;
        ASSERT_EQ(p.items.size(), 4u) << w;
        ASSERT_EQ(p.markers.size(), 1u) << w;
        EXPECT_EQ(p.markers[0].name, d.name);
        EXPECT_EQ(p.markers[0].firstItem, 1);
        EXPECT_EQ(p.markers[0].lastItem, 2);
        EXPECT_EQ(p.markers[0].column, 6);
        EXPECT_EQ(p.items[2].word, "KNOW");  // the ']' is not part of the sign
    }
    // The upper-case spelling and "yn" read the same.
    EXPECT_EQ(parseGloss("[Y/N KNOW]").markers.at(0).name, "yn-question");
    EXPECT_EQ(parseGloss("[yn KNOW]").markers.at(0).name, "yn-question");
    EXPECT_EQ(parseGloss("[MM WALK]").markers.at(0).name, "mouth:MM");
}

TEST(NonManualGloss, IntensityCharacterAndMouthedWordAreReadFromTheParentheses) {
    const GlossParse p = parseGloss("[rs(MARY, 0.8) [neg(0.5) NOT GO]] [mouth(pizza) KNOW] [blink(0.3)]");
    ASSERT_FALSE(p.error) << p.error->message;
    ASSERT_EQ(p.markers.size(), 4u);
    EXPECT_EQ(p.markers[0].name, "role-shift");
    EXPECT_EQ(p.markers[0].argument, "MARY");
    EXPECT_EQ(p.markers[0].argumentColumn, 5);
    EXPECT_DOUBLE_EQ(*p.markers[0].intensity, 0.8);
    EXPECT_EQ(p.markers[1].name, "negation");
    EXPECT_DOUBLE_EQ(*p.markers[1].intensity, 0.5);
    EXPECT_EQ(p.markers[2].argument, "pizza");
    EXPECT_TRUE(p.markers[3].event());
    EXPECT_FALSE(parseGloss("[neg NOT]").markers.at(0).intensity);  // default: 1 (the story's)
}

void expectError(const std::string& gloss, int column, const std::string& part) {
    const GlossParse p = parseGloss(gloss);
    ASSERT_TRUE(p.error) << gloss;
    EXPECT_EQ(p.error->column, column) << gloss << ": " << p.error->message;
    EXPECT_NE(p.error->message.find(part), std::string::npos) << gloss << ": " << p.error->message;
}

TEST(NonManualGloss, UnbalancedMarkersAreRefusedAtTheirColumn) {
    expectError("JOHN [neg NOT KNOW", 6, "not closed");
    expectError("JOHN NOT KNOW]", 14, "without '['");
    expectError("[t MEETING [neg KNOW]", 1, "not closed");
    expectError("[neg NOT KNOW]]", 15, "without '['");
}

TEST(NonManualGloss, OverlappingMarkersOfOneKindAreRefusedAtTheInnerOne) {
    expectError("[y/n JOHN [wh KNOW]]", 11, "overlaps [y/n]");
    expectError("[neg NOT [aff KNOW]]", 10, "overlaps");
    expectError("[mm WALK [puff GO]]", 10, "overlaps");
    expectError("[rs(JOHN) GO [rs(MARY) KNOW]]", 14, "overlaps");
    // Markers of different kinds nest: a negative question, a question in a role shift.
    EXPECT_FALSE(parseGloss("[y/n [neg NOT KNOW]]").error);
    EXPECT_FALSE(parseGloss("[rs(JOHN) [wh KNOW WHERE]]").error);
    EXPECT_FALSE(parseGloss("[t MEETING] [neg NOT KNOW]").error);
}

TEST(NonManualGloss, UnknownEmptyOrMalformedMarkersAreRefusedAtTheirColumn) {
    expectError("JOHN [foo KNOW]", 7, "unknown non-manual marker 'foo'");
    expectError("JOHN [ KNOW]", 6, "starts a non-manual marker");
    expectError("JOHN [neg] KNOW", 6, "marks no signs");
    expectError("JOHN [blink KNOW]", 6, "single event");
    expectError("[neg(2) NOT]", 6, "outside 0.1 to 1.5");
    expectError("[neg(0.5, 0.6) NOT]", 11, "one intensity");
    expectError("[neg(MARY) NOT]", 6, "takes only an intensity");
    expectError("[rs KNOW]", 2, "needs the character");
    expectError("[rs(mary) KNOW]", 5, "in capitals");
    expectError("[mouth(pi zza) KNOW]", 10, "English letters");
    expectError("[neg(0.5 NOT]", 14, "missing ')'");
}

TEST(NonManualStory, ARoleShiftTowardSomeoneWhoIsNotACharacterIsRefusedAtLineAndColumn) {
    try {
        storyFromText("    \"JOHN IX(0.9) [rs(MARIE) KNOW]\"");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 4);
        // The sentence's first character is at column 6 (after 4 spaces and the quote).
        EXPECT_EQ(e.column(), 6 + 17);
        EXPECT_NE(std::string(e.what()).find("did you mean MARY"), std::string::npos) << e.what();
    }
    try {
        storyFromText("    \"JOHN IX(0.9) [neg NOT KNOW\"");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 4);
        EXPECT_EQ(e.column(), 6 + 13);
    }
}

// ---- timing -------------------------------------------------------------------------------

TEST(NonManualTiming, AMarkerRampsInBeforeItsFirstSignHoldsAndRampsOutAfterItsLast) {
    const Timeline t = build(storyFromText("\"JOHN IX(0.9) [neg NOT KNOW]\""));
    const NonManualSpan* neg = findSpan(t, "negation");
    ASSERT_TRUE(neg);
    const auto [start, end] = manual(t, 0, 2, 3);
    EXPECT_NEAR(neg->startSeconds, start - kNonManualLeadSeconds, 1e-9);
    EXPECT_NEAR(neg->endSeconds, end + kNonManualRampOutSeconds, 1e-9);
    // Brows: 0 before the onset, rising over the lead, full over the signs, falling after.
    EXPECT_EQ(value(t, "browDownLeft", neg->startSeconds - 0.01), 0.0);
    const double rising = value(t, "browDownLeft", start - kNonManualLeadSeconds / 2.0);
    EXPECT_GT(rising, 0.1);
    EXPECT_LT(rising, 0.4);
    EXPECT_NEAR(value(t, "browDownLeft", start), 0.5, 1e-9);
    EXPECT_NEAR(value(t, "browDownLeft", 0.5 * (start + end)), 0.5, 1e-9);
    EXPECT_NEAR(value(t, "browDownLeft", end), 0.5, 1e-9);
    EXPECT_GT(value(t, "browDownLeft", end + 0.05), 0.0);
    EXPECT_EQ(value(t, "browDownLeft", neg->endSeconds + 0.01), 0.0);
    // The head shakes both ways over the span, and is still outside it.
    double lowest = 0.0, highest = 0.0;
    for (double s = neg->startSeconds; s <= neg->endSeconds; s += 0.01) {
        lowest = std::min(lowest, value(t, "head.shake", s));
        highest = std::max(highest, value(t, "head.shake", s));
    }
    EXPECT_GT(highest, 0.5 * kHeadshakeRadians);
    EXPECT_LT(lowest, -0.5 * kHeadshakeRadians);
    EXPECT_EQ(value(t, "head.shake", neg->startSeconds - 0.01), 0.0);
}

TEST(NonManualTiming, FasterSigningShortensTheLead) {
    const Timeline t = build(storyFromText("\"JOHN IX(0.9) [t KNOW] COME\""), VerbVersion::Point, 2.0);
    const NonManualSpan* topic = findSpan(t, "topic");
    ASSERT_TRUE(topic);
    EXPECT_NEAR(manual(t, 0, 2, 2).first - topic->startSeconds, kNonManualLeadSeconds / 2.0, 1e-9);
}

TEST(NonManualTiming, IntensityScalesTheMarkersValues) {
    const Timeline full = build(storyFromText("\"JOHN IX(0.9) [wh KNOW WHERE]\""));
    const Timeline half = build(storyFromText("\"JOHN IX(0.9) [wh(0.5) KNOW WHERE]\""));
    const double mid = 0.5 * (manual(full, 0, 2, 3).first + manual(full, 0, 2, 3).second);
    EXPECT_NEAR(value(full, "browDownLeft", mid), 0.8, 1e-9);
    EXPECT_NEAR(value(half, "browDownLeft", mid), 0.4, 1e-9);
    EXPECT_NEAR(value(half, "head.tilt", mid), 0.05, 1e-9);
}

TEST(NonManualTiming, AYesNoQuestionHoldsItsLastSignWithTheBrowsUp) {
    const Timeline plain = build(storyFromText("\"JOHN IX(0.9) KNOW\""));
    const Timeline asked = build(storyFromText("\"JOHN IX(0.9) [y/n KNOW]\""));
    EXPECT_NEAR(asked.durationSeconds - plain.durationSeconds, kYesNoHoldSeconds, 1e-9);
    const auto hold = std::find_if(asked.spans.begin(), asked.spans.end(),
                                   [](const TimelineSpan& s) { return s.kind == SpanKind::Hold && s.item == 2; });
    ASSERT_NE(hold, asked.spans.end());
    EXPECT_EQ(hold->label, "KNOW");
    EXPECT_NEAR(hold->endSeconds - hold->startSeconds, kYesNoHoldSeconds, 1e-9);
    EXPECT_NEAR(value(asked, "browInnerUp", hold->endSeconds), 0.8, 1e-9);
    EXPECT_GT(value(asked, "eyeWideLeft", hold->startSeconds), 0.4);
    EXPECT_GT(value(asked, "head.jut", hold->startSeconds), 10.0);
    // The hold is manual: it stays when non-manuals are off (the face study's sets match).
    EXPECT_NEAR(build(storyFromText("\"JOHN IX(0.9) [y/n KNOW]\""), VerbVersion::Point, 1.0, false).durationSeconds,
                asked.durationSeconds, 1e-12);
}

TEST(NonManualTiming, ATopicEndsWithABlinkEvenSoonAfterASentenceEnd) {
    // Looked at (issue 23): story 03's [t MEETING] ends 0.9 s after the sentence before it, and
    // its blink (Baker & Padden 1978: the topic's boundary) was dropped for being within 1 s of
    // that sentence's blink.
    const Story story = world().loadStory(storyFile(3));
    const Timeline t = build(story);
    double topicEnd = -1.0;
    int topicSentence = -1;
    for (std::size_t s = 0; s < story.sentences.size(); ++s)
        for (const StoryMarker& m : story.sentences[s].markers)
            if (m.marker == "topic") {
                topicSentence = static_cast<int>(s);
                topicEnd = manual(t, topicSentence, m.firstItem, m.lastItem).second;
            }
    ASSERT_GE(topicSentence, 1);
    const double before = manual(t, topicSentence - 1, 0, 1000).second;
    ASSERT_LT(topicEnd - before, kMinimumBlinkGapSeconds);  // the case that dropped it
    const auto blinkAt = [&](double when) {
        return std::any_of(t.nonManualSpans.begin(), t.nonManualSpans.end(), [&](const NonManualSpan& s) {
            return s.marker == "blink" && std::abs(s.startSeconds - when) < 1e-9;
        });
    };
    EXPECT_TRUE(blinkAt(before));
    EXPECT_TRUE(blinkAt(topicEnd));
}

TEST(NonManualTiming, BlinksFallAtEverySentenceEndAndAtANaturalRateBetween) {
    for (int n = 1; n <= 12; ++n) {
        const Story story = world().loadStory(storyFile(n));
        const Timeline t = build(story);
        std::vector<double> blinks;
        for (const NonManualSpan& s : t.nonManualSpans)
            if (s.marker == "blink") blinks.push_back(s.startSeconds);
        ASSERT_FALSE(blinks.empty()) << n;
        EXPECT_TRUE(std::is_sorted(blinks.begin(), blinks.end())) << n;
        // Baker & Padden 1978: a blink as each sentence's last sign ends (unless one just was).
        for (std::size_t s = 0; s < story.sentences.size(); ++s) {
            const double end = manual(t, static_cast<int>(s), 0, 1000).second;
            const bool atEnd = std::any_of(blinks.begin(), blinks.end(), [&](double b) {
                return std::abs(b - end) < 1e-9 || (b < end && end - b < kMinimumBoundaryBlinkGapSeconds);
            });
            EXPECT_TRUE(atEnd) << n << " sentence " << s + 1;
        }
        // Never two blinks closer than the minimum (boundaries' blinks); between the first sign
        // and the last sentence's end, never a gap longer than the longest natural interval.
        for (std::size_t i = 1; i < blinks.size(); ++i) {
            EXPECT_GE(blinks[i] - blinks[i - 1], kMinimumBoundaryBlinkGapSeconds - 1e-9) << n;
            EXPECT_LE(blinks[i] - blinks[i - 1], kBlinkIntervalMaximumSeconds + 1e-9) << n;
        }
        // A natural rate: Bentivoglio et al. 1997 count ~17-26 a minute; 10 to 40 here.
        const double perMinute = 60.0 * static_cast<double>(blinks.size()) / measureTimeline(t).tellingSeconds;
        EXPECT_GE(perMinute, 10.0) << n;
        EXPECT_LE(perMinute, 40.0) << n;
        // Both eyes, shut at the peak.
        EXPECT_NEAR(value(t, "eyeBlinkLeft", blinks[0] + kBlinkCloseSeconds), 1.0, 1e-9);
        EXPECT_NEAR(value(t, "eyeBlinkRight", blinks[0] + kBlinkCloseSeconds), 1.0, 1e-9);
    }
}

TEST(NonManualTiming, ATopicEndsWithABlinkAndAWrittenBlinkFallsBetweenItsSigns) {
    const Timeline t = build(storyFromText("\"[t KNOW] JOHN IX(0.9) COME [blink] WALK\""));
    const double topicEnd = manual(t, 0, 0, 0).second;
    const double between = 0.5 * (manual(t, 0, 3, 3).second + manual(t, 0, 4, 4).first);
    bool atTopic = false, written = false;
    for (const NonManualSpan& s : t.nonManualSpans) {
        atTopic |= s.marker == "blink" && std::abs(s.startSeconds - topicEnd) < 1e-9;
        written |= s.marker == "blink" && std::abs(s.startSeconds - between) < 1e-9;
    }
    EXPECT_TRUE(atTopic);
    EXPECT_TRUE(written);
}

TEST(NonManualTiming, ARoleShiftTurnsTorsoHeadAndGazeTowardTheCharacter) {
    const Timeline t = build(storyFromText("\"JOHN IX(0.9) [rs(MARY) KNOW COME]\""));
    const auto [start, end] = manual(t, 0, 2, 3);
    const double mid = 0.5 * (start + end);
    // MARY stands at -0.6, on the signer's left: + toward the left (timeline.hpp).
    EXPECT_GT(value(t, "torso.turn", mid), 0.1);
    EXPECT_GT(value(t, "head.shake", mid), 0.1);
    EXPECT_GT(value(t, "torso.shift", mid), 0.0);
    const GazeSample g = sampleGaze(t.gaze, mid);
    ASSERT_TRUE(g.from->targetMm && g.to->targetMm);
    EXPECT_NEAR(glm::length(*g.to->targetMm - arcPoint(-0.6)), 0.0, 1e-9);
    const NonManualSpan* rs = findSpan(t, "role-shift");
    ASSERT_TRUE(rs);
    EXPECT_EQ(rs->text, "MARY");
    // Toward JOHN (0.9, right): the other way.
    const Timeline right = build(storyFromText("\"MARY IX(-0.6) [rs(JOHN) KNOW COME]\""));
    EXPECT_LT(value(right, "torso.turn", 0.5 * (manual(right, 0, 2, 3).first + manual(right, 0, 2, 3).second)), -0.1);
}

TEST(NonManualTiming, EachMouthMorphemeMovesItsMouthChannels) {
    const std::vector<std::pair<std::string, std::string>> cases{
        {"mm", "mouthPressLeft"}, {"oo", "mouthPucker"}, {"cha", "jawOpen"},   {"th", "tongueOut"},
        {"pah", "jawOpen"},       {"cs", "mouthStretchRight"}, {"puff", "cheekPuff"}};
    for (const auto& c : cases) {
        const Timeline t = build(storyFromText("\"JOHN IX(0.9) [" + c.first + " WALK COME]\""));
        const auto range = manual(t, 0, 2, 3);
        double peak = 0.0;
        for (double s = range.first; s <= range.second; s += 0.01) peak = std::max(peak, value(t, c.second, s));
        EXPECT_GT(peak, 0.3) << c.first;
        EXPECT_EQ(value(t, c.second, range.first - kNonManualLeadSeconds - 0.01), 0.0) << c.first;
    }
}

TEST(NonManualTiming, EveryChannelIsAnArkitBlendshapeOrABodyChannelOfTheSeam) {
    // Apple's ARKit-52 blendshape names and the seam's head/torso/shoulder channels
    // (stimuli/story/timeline.hpp): the names a signer's body and a lab's avatar map.
    const std::vector<std::string> known{
        "browDownLeft", "browDownRight", "browInnerUp", "browOuterUpLeft", "browOuterUpRight", "cheekPuff",
        "cheekSquintLeft", "cheekSquintRight", "eyeBlinkLeft", "eyeBlinkRight", "eyeLookDownLeft", "eyeLookDownRight",
        "eyeLookInLeft", "eyeLookInRight", "eyeLookOutLeft", "eyeLookOutRight", "eyeLookUpLeft", "eyeLookUpRight",
        "eyeSquintLeft", "eyeSquintRight", "eyeWideLeft", "eyeWideRight", "jawForward", "jawLeft", "jawOpen", "jawRight",
        "mouthClose", "mouthDimpleLeft", "mouthDimpleRight", "mouthFrownLeft", "mouthFrownRight", "mouthFunnel",
        "mouthLeft", "mouthLowerDownLeft", "mouthLowerDownRight", "mouthPressLeft", "mouthPressRight", "mouthPucker",
        "mouthRight", "mouthRollLower", "mouthRollUpper", "mouthShrugLower", "mouthShrugUpper", "mouthSmileLeft",
        "mouthSmileRight", "mouthStretchLeft", "mouthStretchRight", "mouthUpperUpLeft", "mouthUpperUpRight",
        "noseSneerLeft", "noseSneerRight", "tongueOut", "head.nod", "head.shake", "head.tilt", "head.jut", "torso.lean",
        "torso.turn", "torso.shift", "shoulders.raise", "shoulder.raiseLeft", "shoulder.raiseRight"};
    std::string sentence = "\"JOHN IX(0.9) [nod]";
    for (const MarkerDefinition& d : markerDefinitions()) {
        if (d.markerClass == MarkerClass::Event) continue;
        const std::string w(d.written);
        sentence += " [" + (d.argument == MarkerArgument::Character ? w + "(MARY)" : d.argument == MarkerArgument::Word ? w + "(know)" : w) + " KNOW]";
    }
    const Timeline t = build(storyFromText(sentence + "\""));
    EXPECT_GT(t.nonManuals.size(), 30u);
    for (const NonManualTrack& track : t.nonManuals) {
        EXPECT_NE(std::find(known.begin(), known.end(), track.channel), known.end()) << track.channel;
        EXPECT_EQ(track.keys.front().value, 0.0) << track.channel;  // every channel rests at its ends
        EXPECT_EQ(track.keys.back().value, 0.0) << track.channel;
    }
}

// ---- same in every version; the switch -----------------------------------------------------

TEST(NonManualVersions, ChannelsSpansAndGazeOutsideVerbsAreIdenticalInTheFourVersions) {
    int marked = 0;
    for (int n = 1; n <= 12; ++n) {
        const Story story = world().loadStory(storyFile(n));
        const Timeline first = build(story, kVersions[0]);
        for (VerbVersion v : kVersions) {
            const Timeline t = build(story, v);
            ASSERT_EQ(t.nonManuals.size(), first.nonManuals.size()) << n;
            for (std::size_t c = 0; c < t.nonManuals.size(); ++c) {
                EXPECT_EQ(t.nonManuals[c].channel, first.nonManuals[c].channel);
                ASSERT_EQ(t.nonManuals[c].keys.size(), first.nonManuals[c].keys.size()) << n;
                for (std::size_t k = 0; k < t.nonManuals[c].keys.size(); ++k) {
                    EXPECT_EQ(t.nonManuals[c].keys[k].timeSeconds, first.nonManuals[c].keys[k].timeSeconds);
                    EXPECT_EQ(t.nonManuals[c].keys[k].value, first.nonManuals[c].keys[k].value);
                }
            }
            ASSERT_EQ(t.nonManualSpans.size(), first.nonManualSpans.size()) << n;
            for (std::size_t s = 0; s < t.nonManualSpans.size(); ++s) {
                EXPECT_EQ(t.nonManualSpans[s].marker, first.nonManualSpans[s].marker);
                EXPECT_EQ(t.nonManualSpans[s].startSeconds, first.nonManualSpans[s].startSeconds);
                EXPECT_EQ(t.nonManualSpans[s].endSeconds, first.nonManualSpans[s].endSeconds);
            }
        }
        for (const NonManualSpan& s : first.nonManualSpans) marked += s.marker != "blink";
    }
    EXPECT_GE(marked, 4);  // the default stories use markers (issue 23 §6)
}

TEST(NonManualVersions, AtLeastFourDefaultStoriesAskNegateOrTopicalize) {
    int stories = 0;
    for (int n = 1; n <= 12; ++n) {
        const Story story = world().loadStory(storyFile(n));
        bool grammar = false;
        for (const StorySentence& s : story.sentences)
            for (const StoryMarker& m : s.markers)
                grammar |= m.marker == "yn-question" || m.marker == "wh-question" || m.marker == "negation" ||
                           m.marker == "topic";
        stories += grammar;
    }
    EXPECT_GE(stories, 4);
}

TEST(NonManualSwitch, AStoryOrOptionSwitchesTheFaceOffAndLeavesTheHandsAlone) {
    const std::string sentences = "\"JOHN IX(0.9) [neg NOT KNOW]\",\n\"[rs(MARY) [y/n COME]]\"";
    const Timeline on = build(storyFromText(sentences));
    const Timeline off = build(storyFromText(sentences, ",\n  \"nonManuals\": false"));
    const Timeline option = build(storyFromText(sentences), VerbVersion::Point, 1.0, false);
    EXPECT_FALSE(on.nonManuals.empty());
    for (const Timeline* t : {&off, &option}) {
        EXPECT_TRUE(t->nonManuals.empty());
        EXPECT_TRUE(t->nonManualSpans.empty());
        EXPECT_EQ(t->durationSeconds, on.durationSeconds);
        ASSERT_EQ(t->right.size(), on.right.size());
        for (std::size_t k = 0; k < on.right.size(); ++k) EXPECT_EQ(t->right[k].timeSeconds, on.right[k].timeSeconds);
    }
    // The role shift's gaze goes with the face.
    EXPECT_NE(off.gaze.size(), on.gaze.size());
    try {
        storyFromText(sentences, ",\n  \"nonManuals\": \"no\"");
        FAIL() << "accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "/nonManuals");
    }
}

TEST(NonManualSwitch, AStudysRenderSwitchesThemOffAndSaysSo) {
    const std::string study = R"({
  "format": "signstim-study", "version": 1, "title": "T", "seed": 3, "participants": 8,
  "versions": ["point", "vector", "animator", "uninflected"],
  "stories": ["a.json", "b.json", "c.json", "d.json"],
  "render": {"size": "640x480", "fps": 30, "msaa": 4, "rate": 1, "nonManuals": false}
})";
    const StudyFile file = parseStudyFile(parseJsonText(study, "study.json"));
    EXPECT_FALSE(file.render.nonManuals);
    EXPECT_FALSE(file.quick.nonManuals);  // quick takes the render's
    EXPECT_NE(file.render.text().find("no non-manuals"), std::string::npos);
    std::string on = study;
    on.replace(on.find(", \"nonManuals\": false"), 21, "");
    EXPECT_TRUE(parseStudyFile(parseJsonText(on, "study.json")).render.nonManuals);
}

// ---- story --json ------------------------------------------------------------------------------

TEST(NonManualJson, TheTimelineJsonCarriesTheChannelsAndTheSpans) {
    const Timeline t = build(storyFromText("\"JOHN IX(0.9) [neg NOT KNOW]\", \"[rs(MARY) COME]\""));
    const nlohmann::json j = nlohmann::json::parse(formatTimelineJson(t));
    ASSERT_TRUE(j.contains("nonManuals"));
    const auto& channels = j["nonManuals"]["channels"];
    ASSERT_EQ(channels.size(), t.nonManuals.size());
    bool shake = false;
    for (const auto& c : channels)
        if (c["channel"] == "head.shake") {
            shake = true;
            EXPECT_EQ(c["keys"].size(), findNonManual(t, "head.shake")->keys.size());
            EXPECT_EQ(c["keys"][0].size(), 2u);  // [time, value]
        }
    EXPECT_TRUE(shake);
    bool negation = false, roleShift = false;
    for (const auto& s : j["nonManuals"]["spans"]) {
        negation |= s["marker"] == "negation" && s["sentence"] == 1;
        roleShift |= s["marker"] == "role-shift" && s["sentence"] == 2 && s["text"] == "MARY";
    }
    EXPECT_TRUE(negation);
    EXPECT_TRUE(roleShift);
}

TEST(NonManualJson, TheSameStoryBlinksTheSameAndAnotherStoryOtherwise) {
    const Story a = world().loadStory(storyFile(1));
    EXPECT_EQ(formatTimelineJson(build(a)), formatTimelineJson(build(a)));
    const Story b = world().loadStory(storyFile(2));
    std::vector<double> blinksA, blinksB;
    for (const NonManualSpan& s : build(a).nonManualSpans) blinksA.push_back(s.startSeconds);
    for (const NonManualSpan& s : build(b).nonManualSpans) blinksB.push_back(s.startSeconds);
    EXPECT_NE(blinksA, blinksB);
    EXPECT_NE(describeNonManuals(a, build(a)).find("role-shift 1, yn-question 1"), std::string::npos)
        << describeNonManuals(a, build(a));
}

}  // namespace
}  // namespace signstim::stimuli
