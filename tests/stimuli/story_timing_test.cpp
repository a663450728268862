// Story timing (stimuli/story/timeline.hpp, docs/stories.md "Timing", SPEC §6.2-6.3): the
// natural preset's pace on the default stories and phase-2 sentences, boundary holds instead
// of rest, Huenerfauth's boundary and repetition rules, coarticulated keys, the speed limit,
// the legacy preset, and the `timing` object's errors.
#include "stimuli/story/story_world.hpp"
#include "stimuli/study/study.hpp"
#include "stimuli/story/timeline_builder.hpp"

#include <gtest/gtest.h>

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

Story storyFromText(const std::string& sentences, const std::string& timing = "") {
    const std::string text = R"({"format": "signstim-story", "version": 1, "title": "T",
  "characters": [{"gloss": "JOHN", "position": 0.9}, {"gloss": "MARY", "position": -0.6}],
  "sentences": [)" + sentences + "]" +
                             (timing.empty() ? "" : ",\n  \"timing\": " + timing) + "}";
    return parseStory(parseJsonText(text, "timing-test.json"), world().vocabulary());
}

Timeline build(const Story& story, VerbVersion v = VerbVersion::Point) {
    // The natural preset (TimelineOptions' defaults; a story's own `timing` on top of it).
    StoryTiming timing = story.timing;
    if (!timing.given()) timing.preset = "natural";
    return buildTimeline(story, v, world().sources(story), timelineOptionsFor(timing, 1.0));
}

std::string storyFile(int n) {
    char name[64];
    std::snprintf(name, sizeof name, "/stories/story-%02d.json", n);
    return kScenes + name;
}

// Where the hand's reference point is at t (nullopt at rest): the sampled blend of positions.
std::optional<glm::dvec3> handAt(const std::vector<TimelineKey>& track, double t) {
    const TimelineSample s = sampleTrack(track, t);
    if (s.from->rest || s.to->rest) return std::nullopt;
    return s.from->pose.positionMm + s.blend * (s.to->pose.positionMm - s.from->pose.positionMm);
}

TEST(StoryTiming, DefaultStoriesSignNearConversationalPaceAndFingerspellAtFourToSixLettersPerSecond) {
    // SPEC §6.3: conversational ASL ~2-2.3 signs/s; fingerspelling 2-6 letters/s, fluent near
    // the top. The wrist speed limit (SPEC §6.2) holds the densest stories a little below 1.7.
    double sum = 0.0;
    for (int n = 1; n <= 12; ++n) {
        const Story story = world().loadStory(storyFile(n));
        const TimelineMeasures m = measureTimeline(build(story));
        EXPECT_GE(m.signsPerSecond(), 1.5) << n;
        EXPECT_LE(m.signsPerSecond(), 2.3) << n;
        if (m.letters > 0) {
            EXPECT_GE(m.lettersPerSecond(), 4.0) << n;
            EXPECT_LE(m.lettersPerSecond(), 6.0) << n;
        }
        sum += m.signsPerSecond();
    }
    EXPECT_GE(sum / 12.0, 1.7);
    // The legacy preset, for comparison, is much slower.
    const Story first = world().loadStory(storyFile(1));
    EXPECT_LT(measureTimeline(buildTimeline(first, VerbVersion::Point, world().sources(first), legacyTimelineOptions()))
                  .signsPerSecond(),
              1.2);
}

TEST(StoryTiming, PhaseTwoSentencesAloneKeepThePaceAndTheirSlotsEqual) {
    const Story all = world().loadStory(kScenes + "/studies/phase2-sentences.json");
    for (std::size_t s = 0; s < all.sentences.size(); ++s) {
        Story one = all;
        one.sentences = {all.sentences[s]};
        std::vector<double> durations;
        for (VerbVersion v : kVersions) durations.push_back(build(one, v).durationSeconds);
        for (double d : durations) EXPECT_EQ(d, durations.front()) << s;
        // Each is five items, two of them a name and IX far out on the arc and a verb sweeping
        // between them: the speed limit holds these near 1.4 signs/s.
        const TimelineMeasures m = measureTimeline(build(one));
        EXPECT_GE(m.signsPerSecond(), 1.3) << s;
        EXPECT_LE(m.signsPerSecond(), 2.6) << s;
    }
}

TEST(StoryTiming, SentencesEndInABoundaryHoldAndTheHandsRestOnlyAtTheEnds) {
    const Story story = world().loadStory(storyFile(2));
    for (VerbVersion v : kVersions) {
        const Timeline t = build(story, v);
        // Rest spans: the opening one and the closing one (the closing may be inside a verb slot).
        int rests = 0;
        for (const TimelineSpan& span : t.spans) rests += span.kind == SpanKind::Rest;
        EXPECT_LE(rests, 2);
        EXPECT_EQ(t.spans.front().kind, SpanKind::Rest);
        // Between the first and the last sign no hand key is at rest... unless that hand
        // never signs in between (the left hand rests while only the right signs).
        double first = t.durationSeconds, last = 0.0;
        for (const TimelineKey& k : t.right)
            if (!k.rest) {
                first = std::min(first, k.timeSeconds);
                last = std::max(last, k.timeSeconds);
            }
        for (const TimelineKey& k : t.right)
            if (k.timeSeconds > first && k.timeSeconds < last) {
                EXPECT_FALSE(k.rest) << toString(v) << " " << k.timeSeconds;
            }
        // Each boundary: a hold of 150-400 ms with the hands still (its own span, or inside a verb's slot).
        int boundaries = 0;
        for (const TimelineSpan& span : t.spans) {
            if (span.kind != SpanKind::Hold || span.item != -1) continue;  // a boundary hold (not a HOLD item)
            ++boundaries;
            const double held = span.endSeconds - span.startSeconds;
            EXPECT_GE(held, 0.15 - 1e-9);
            EXPECT_LE(held, 0.4 + 1e-9);
            const auto a = handAt(t.right, span.startSeconds + 0.01), b = handAt(t.right, span.endSeconds - 0.01);
            ASSERT_TRUE(a && b);
            EXPECT_LT(glm::distance(*a, *b), 1e-9);
        }
        int slotBoundaries = 0;  // sentences that end in a verb hold inside its slot
        for (std::size_t s = 0; s + 1 < story.sentences.size(); ++s)
            slotBoundaries += story.sentences[s].items.back().kind == StoryItemKind::Verb;
        EXPECT_EQ(boundaries + slotBoundaries, static_cast<int>(story.sentences.size()) - 1) << toString(v);
        EXPECT_GT(t.pauseSeconds, 0.0);
    }
    // The legacy preset goes back to rest between sentences.
    const Timeline legacy = buildTimeline(story, VerbVersion::Point, world().sources(story), legacyTimelineOptions());
    int rests = 0;
    for (const TimelineSpan& span : legacy.spans) rests += span.kind == SpanKind::Rest;
    EXPECT_GT(rests, 2);
}

double keysOf(const Timeline& t, const std::string& label, int occurrence) {
    int seen = 0;
    for (const TimelineSpan& span : t.spans)
        if (span.label == label && seen++ == occurrence) return span.keysEndSeconds - span.keysStartSeconds;
    ADD_FAILURE() << label << " #" << occurrence;
    return 0.0;
}

TEST(StoryTiming, ASignBeforeABoundaryIsTwelvePercentLongerAndARepeatedOneTwelvePercentShorter) {
    // Huenerfauth 2008-09 (SPEC §6.3). MY is short and near the chest: no speed limit stretches it.
    const Timeline mid = build(storyFromText(R"("MY HELP", "HELP")"));
    const Timeline end = build(storyFromText(R"("HELP MY", "HELP")"));
    EXPECT_NEAR(keysOf(end, "MY", 0) / keysOf(mid, "MY", 0), 1.12, 1e-6);
    const Timeline twice = build(storyFromText(R"("MY MY HELP")"));
    EXPECT_NEAR(keysOf(twice, "MY", 1) / keysOf(twice, "MY", 0), 0.88, 1e-6);
    // Named parameters: the rules can be switched off from the story file.
    const Timeline off = build(storyFromText(R"("HELP MY", "HELP")", R"({"preset": "natural", "boundaryLengthening": 1})"));
    EXPECT_NEAR(keysOf(off, "MY", 0) / keysOf(mid, "MY", 0), 1.0, 1e-6);
}

TEST(StoryTiming, NoStretchOfAnyVersionPeaksAboveTheWristSpeedLimit) {
    // SPEC §6.2: 2.5 m/s. The hand's reference point, sampled every 2 ms in every version of
    // every default story, moves slower than the builder's bound (the signer's posed wrist is
    // measured by `story --check`, tests/app).
    for (int n = 1; n <= 12; ++n) {
        const Story story = world().loadStory(storyFile(n));
        for (VerbVersion v : kVersions) {
            const Timeline t = build(story, v);
            double peak = 0.0;
            for (const auto* track : {&t.right, &t.left})
                for (double time = 0.0; time + 0.002 <= t.durationSeconds; time += 0.002) {
                    const auto a = handAt(*track, time), b = handAt(*track, time + 0.002);
                    if (a && b) peak = std::max(peak, glm::distance(*a, *b) / 0.002);
                }
            EXPECT_LE(peak, TimelineOptions{}.peakSpeedMmPerSecond * 1.001) << n << " " << toString(v);
            EXPECT_GT(peak, 500.0) << n << " " << toString(v);
        }
    }
}

TEST(StoryTiming, HandsFlowThroughKeysOfAContinuingMovementAndStopWhereItReverses) {
    const Story story = world().loadStory(storyFile(1));
    const Timeline t = build(story);
    int through = 0;
    for (std::size_t k = 1; k + 1 < t.right.size(); ++k) {
        const TimelineKey& key = t.right[k];
        if (!key.passThrough) continue;
        const glm::dvec3 d1 = key.pose.positionMm - t.right[k - 1].pose.positionMm;
        const glm::dvec3 d2 = t.right[k + 1].pose.positionMm - key.pose.positionMm;
        if (glm::length(d1) < 1.0 || glm::length(d2) < 1.0 || glm::dot(d1, d2) <= 0.2 * glm::length(d1) * glm::length(d2))
            continue;
        ++through;
        // Moving at the key (slower where the path turns): not stopped, unlike at a hold.
        const auto before = handAt(t.right, key.timeSeconds - 0.001), after = handAt(t.right, key.timeSeconds + 0.001);
        ASSERT_TRUE(before && after);
        EXPECT_GT(glm::distance(*before, *after) / 0.002, 10.0) << key.timeSeconds;
    }
    EXPECT_GT(through, 3);
    // A hold stops the hand: the key before a boundary hold is not crossed.
    for (const TimelineSpan& span : t.spans)
        if (span.kind == SpanKind::Hold && span.item == -1) {
            const auto a = handAt(t.right, span.startSeconds - 0.001), b = handAt(t.right, span.startSeconds);
            ASSERT_TRUE(a && b);
            EXPECT_LT(glm::distance(*a, *b) / 0.001, 5.0);
        }
    // The legacy preset stops at every key.
    const Timeline legacy = buildTimeline(story, VerbVersion::Point, world().sources(story), legacyTimelineOptions());
    for (const TimelineKey& k : legacy.right) EXPECT_FALSE(k.passThrough);
    // The ease keeps within its ends and is minimum jerk without slopes.
    for (double u = 0.0; u <= 1.0; u += 0.01) {
        EXPECT_DOUBLE_EQ(hermiteEase(u, 0.0, 0.0), minimumJerk(u));
        const double e = hermiteEase(u, 1.875, 1.875);
        EXPECT_GE(e, 0.0);
        EXPECT_LE(e, 1.0 + 1e-12);
    }
}

TEST(StoryTiming, TimingObjectMistakesNameFileLineAndField) {
    const auto message = [](const std::string& timing) {
        try {
            storyFromText(R"("MY HELP")", timing);
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message(R"({"pauseShare": 0.9})").find("timing-test.json:4"), std::string::npos) << message(R"({"pauseShare": 0.9})");
    EXPECT_NE(message(R"({"pauseShare": 0.9})").find("/timing/pauseShare"), std::string::npos);
    EXPECT_NE(message(R"({"pauseShare": 0.9})").find("0.5"), std::string::npos);
    EXPECT_NE(message(R"({"preset": "fast"})").find("/timing/preset"), std::string::npos);
    EXPECT_NE(message(R"({"coarticulation": 1})").find("true or false"), std::string::npos);
    EXPECT_NE(message(R"({"signsPerSecond": 2})").find("unknown timing field 'signsPerSecond'"), std::string::npos);
    EXPECT_NE(message(R"({"boundaryHoldMinimumSeconds": 0.5})").find("minimum is above its maximum"), std::string::npos);
    EXPECT_NE(message(R"([1])").find("/timing"), std::string::npos);
    EXPECT_EQ(message(R"({"preset": "legacy", "pauseShare": 0.1, "coarticulation": true})"), "no error");
    // The legacy preset is today's timing, field for field.
    const Story legacy = storyFromText(R"("MY HELP", "HELP")", R"({"preset": "legacy"})");
    EXPECT_EQ(formatTimelineJson(build(legacy)),
              formatTimelineJson(buildTimeline(legacy, VerbVersion::Point, world().sources(legacy), legacyTimelineOptions())));
    EXPECT_EQ(describeTiming(storyFromText(R"("MY")", R"({"preset": "legacy", "pauseShare": 0.1})").timing),
              "legacy, pauseShare 0.1");
}

TEST(StoryTiming, AStudyFilesRenderTimingIsReadCheckedAndNamedInItsSettings) {
    const auto study = [](const std::string& timing) {
        return parseStudyFile(parseJsonText(R"({
  "format": "signstim-study", "version": 1, "title": "T", "seed": 3, "participants": 8,
  "versions": ["point", "vector", "animator", "uninflected"],
  "stories": ["a.json", "b.json", "c.json", "d.json", "e.json", "f.json", "g.json", "h.json"],
  "phase2": {"story": "s.json", "sentences": [2, 1, 3, 4]},
  "render": {"size": "640x480", "fps": 30, "msaa": 4, "rate": 1,
             "timing": )" + timing + R"(}
})",
                                            "study.json"));
    };
    const StudyFile legacy = study(R"({"preset": "legacy"})");
    EXPECT_TRUE(legacy.render.timing.given());
    EXPECT_EQ(legacy.render.timing.preset, "legacy");
    EXPECT_EQ(legacy.quick.timing.preset, "legacy");  // the quick preview tells it the same way
    EXPECT_NE(legacy.render.text().find("timing legacy"), std::string::npos) << legacy.render.text();
    try {
        study(R"({"repetitionShortening": 0.2})");
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("study.json:7"), std::string::npos) << what;
        EXPECT_NE(what.find("/render/timing/repetitionShortening"), std::string::npos) << what;
    }
}

}  // namespace
}  // namespace signstim::stimuli
