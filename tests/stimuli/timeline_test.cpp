// Timelines (stimuli/story/timeline.hpp): a story in each of the four versions differs only inside
// the verb slots; the hands start and end at rest and move without jumps; fingerspelled
// letters are held; gaze follows pointing and the verb's object.
#include "stimuli/story/timeline_builder.hpp"

#include "stimuli/verbs/signing_space.hpp"
#include "stimuli/verbs/sora.hpp"

#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cstring>
#include <string>

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
  "locations": {"chest": [0, 0, 110], "chin": [0, 255, 95]},
  "signs": [
    {"gloss": "MY", "hands": ["right"], "keyframes": {"right": [
      {"time": 0, "at": "chest", "offset": [0, 0, 60], "touch": "palm", "fingers": [-0.3, 1, 0], "palm": [0, 0, -1], "handshape": "B"},
      {"time": 0.25, "at": "chest", "touch": "palm", "fingers": [-0.3, 1, 0], "palm": [0, 0, -1], "handshape": "B"}]}},
    {"gloss": "HELP", "hands": ["right", "left"], "contact": ["hands"], "keyframes": {
      "right": [
        {"time": 0, "position": [0, -100, 300], "fingers": [0, 0, 1], "palm": [-1, 0, 0], "handshape": "A"},
        {"time": 0.4, "position": [0, 20, 300], "fingers": [0, 0, 1], "palm": [-1, 0, 0], "handshape": "A"}],
      "left": [
        {"time": 0, "position": [-20, -150, 280], "fingers": [0.3, 0, 1], "palm": [0, 1, 0], "handshape": "B"},
        {"time": 0.4, "position": [-20, -30, 280], "fingers": [0.3, 0, 1], "palm": [0, 1, 0], "handshape": "B"}]}}
  ]})", "test-lexicon.json"), shapes, model);
    Story story = parseStory(parseJsonText(R"({
  "format": "signstim-story", "version": 1, "title": "T",
  "characters": [{"gloss": "JOHN", "position": 0.9}, {"gloss": "MARY", "position": -0.6}],
  "sentences": [
    "JOHN IX(0.9) MY",
    "JOHN ASK MARY IX(-0.6) HELP",
    "IX(MARY) TELL IX(JOHN) HOLD",
    "fs-ANN MY"
  ],
  "questions": [{"question": "Q", "choices": ["a", "b", "c"], "answer": "A", "probes": {"sentence": 2, "verb": "ASK"}}]
})", "test-story.json"), StoryVocabulary{&verbs, lexicon.glosses(), nullptr, nullptr});

    TimelineSources sources() const {
        TimelineSources s;
        s.lexicon = &lexicon;
        s.shapes = &shapes;
        s.verbs = [this](const std::string& verb, VerbVersion version, double subject, double object, int, int) {
            return synthesizeVerb(VerbSources{&verbs, &models, kSource + "/scenes/animator"}, verb, version, subject, object);
        };
        return s;
    }
};

const World& world() {
    static const World w;
    return w;
}

const std::array<VerbVersion, 4> kVersions{VerbVersion::Point, VerbVersion::Vector, VerbVersion::Animator,
                                           VerbVersion::Uninflected};

// What a hand does at t, as plain numbers: identical samples give identical frames.
std::string handState(const std::vector<TimelineKey>& track, double t) {
    const TimelineSample s = sampleTrack(track, t);
    char text[512];
    auto pose = [](const TimelineKey& k) {
        char p[200];
        if (k.rest) return std::string("rest");
        std::snprintf(p, sizeof p, "%.17g,%.17g,%.17g|%.17g,%.17g,%.17g,%.17g|%s", k.pose.positionMm.x, k.pose.positionMm.y,
                      k.pose.positionMm.z, k.pose.orientation.w, k.pose.orientation.x, k.pose.orientation.y,
                      k.pose.orientation.z, k.handshape.c_str());
        return std::string(p);
    };
    std::snprintf(text, sizeof text, "%s -> %s @ %.17g", pose(*s.from).c_str(), pose(*s.to).c_str(), s.blend);
    return text;
}

std::string gazeState(const std::vector<GazeKey>& gaze, double t) {
    const GazeSample s = sampleGaze(gaze, t);
    auto target = [](const GazeKey& k) {
        if (!k.targetMm) return std::string("viewer");
        char p[120];
        std::snprintf(p, sizeof p, "%.17g,%.17g,%.17g", k.targetMm->x, k.targetMm->y, k.targetMm->z);
        return std::string(p);
    };
    return target(*s.from) + " -> " + target(*s.to) + " @ " + std::to_string(s.blend);
}

bool insideVerb(const Timeline& timeline, double t) {
    for (const TimelineSpan& span : timeline.spans)
        if (span.kind == SpanKind::Verb && t > span.startSeconds - 1e-9 && t < span.endSeconds + 1e-9) return true;
    return false;
}

TEST(Timeline, EveryFrameOutsideTheVerbSlotsIsIdenticalInTheFourVersions) {
    std::vector<Timeline> timelines;
    for (VerbVersion v : kVersions) timelines.push_back(buildTimeline(world().story, v, world().sources()));
    const Timeline& first = timelines.front();
    int compared = 0, insideSlots = 0, differingInside = 0;
    for (const Timeline& other : timelines) {
        ASSERT_EQ(other.durationSeconds, first.durationSeconds);
        ASSERT_EQ(other.spans.size(), first.spans.size());
        for (std::size_t i = 0; i < first.spans.size(); ++i) {
            EXPECT_EQ(other.spans[i].startSeconds, first.spans[i].startSeconds) << i;
            EXPECT_EQ(other.spans[i].endSeconds, first.spans[i].endSeconds) << i;
        }
    }
    for (int frame = 0; frame / 30.0 <= first.durationSeconds; ++frame) {
        const double t = frame / 30.0;
        if (insideVerb(first, t)) {
            ++insideSlots;
            differingInside += handState(timelines[0].right, t) != handState(timelines[3].right, t);
            continue;
        }
        for (const Timeline& other : timelines) {
            EXPECT_EQ(handState(other.right, t), handState(first.right, t)) << other.version << " at " << t;
            EXPECT_EQ(handState(other.left, t), handState(first.left, t)) << other.version << " at " << t;
            EXPECT_EQ(gazeState(other.gaze, t), gazeState(first.gaze, t)) << other.version << " at " << t;
        }
        ++compared;
    }
    EXPECT_GT(compared, 60);
    EXPECT_GT(insideSlots, 20);
    EXPECT_GT(differingInside, 5) << "point and uninflected should differ inside the verb slots";
}

TEST(Timeline, StartsAndEndsAtRestWithTimesIncreasing) {
    const Timeline t = buildTimeline(world().story, VerbVersion::Animator, world().sources());
    for (const auto* track : {&t.right, &t.left}) {
        EXPECT_TRUE(track->front().rest);
        EXPECT_TRUE(track->back().rest);
        EXPECT_EQ(track->front().timeSeconds, 0.0);
        EXPECT_DOUBLE_EQ(track->back().timeSeconds, t.durationSeconds);
        for (std::size_t i = 1; i < track->size(); ++i) EXPECT_GE((*track)[i].timeSeconds, (*track)[i - 1].timeSeconds);
    }
    for (std::size_t i = 1; i < t.gaze.size(); ++i) EXPECT_GT(t.gaze[i].timeSeconds, t.gaze[i - 1].timeSeconds);
}

TEST(Timeline, SpansNameTheirItemsOwnKeysAndWhatTheyTouch) {
    // Each span's own keys lie within it, both hands have keys where they begin and end (the
    // transitions lie between), and a sign or verb carries its "contact".
    for (VerbVersion v : kVersions) {
        const Timeline t = buildTimeline(world().story, v, world().sources());
        bool sawHelp = false, sawTell = false;
        for (const TimelineSpan& span : t.spans) {
            EXPECT_LE(span.startSeconds, span.keysStartSeconds) << span.label;
            EXPECT_LE(span.keysStartSeconds, span.keysEndSeconds) << span.label;
            EXPECT_LE(span.keysEndSeconds, span.endSeconds + 1e-12) << span.label;
            for (const auto* track : {&t.right, &t.left}) {
                const auto hasKeyAt = [&](double s) {
                    return std::any_of(track->begin(), track->end(), [&](const TimelineKey& k) { return k.timeSeconds == s; });
                };
                EXPECT_TRUE(hasKeyAt(span.keysStartSeconds)) << span.label;
                EXPECT_TRUE(hasKeyAt(span.keysEndSeconds)) << span.label;
            }
            if (span.label == "HELP") {
                sawHelp = true;
                EXPECT_TRUE(span.contact.hands);
                EXPECT_FALSE(span.contact.body);
            }
            if (span.label == "TELL") {
                sawTell = true;
                EXPECT_TRUE(span.contact.body);  // scenes/verbs.json: from the mouth
            }
            if (span.label == "MY" || span.kind == SpanKind::Pointing) {
                EXPECT_FALSE(span.contact.hands || span.contact.body) << span.label;
            }
        }
        EXPECT_TRUE(sawHelp && sawTell);
    }
}

TEST(Timeline, PointingAcrossTheChestStaysInFrontOfItAndAimsAtTheReferent) {
    // IX toward the far left: reached from the right shoulder, the hand would be inside the
    // chest; it stays in front and the index still aims at the referent. IX toward the far
    // right keeps the plain reach.
    const Timeline t = buildTimeline(world().story, VerbVersion::Point, world().sources());
    const TimelineOptions options;
    bool left = false, right = false;
    for (const TimelineSpan& span : t.spans) {
        if (span.kind != SpanKind::Pointing) continue;
        const TimelineSample s = sampleTrack(t.right, 0.5 * (span.keysStartSeconds + span.keysEndSeconds));
        const HandPose& pose = s.from->pose;
        // In front of the chest (the default signer's is 340 mm wide), not in it.
        if (pose.positionMm.x < 170.0) {
            EXPECT_GE(pose.positionMm.z, options.pointingMinimumForwardMm - 1e-9);
        }
        // Which referent: the closest arc point to the index's line.
        const glm::dvec3 fingers = fingersDirection(pose.orientation);
        double best = 1e9, position = 0.0;
        for (double p = -1.0; p <= 1.0; p += 0.01) {
            const glm::dvec3 to = arcPoint(p) - pose.positionMm;
            const double miss = glm::length(to - glm::dot(to, fingers) * fingers);
            if (miss < best) best = miss, position = p;
        }
        EXPECT_LT(best, 1.0) << span.label;
        left = left || position < -0.5;
        right = right || position > 0.5;
    }
    EXPECT_TRUE(left && right);
}

// Position of a non-resting sample; the rest place is the signer's, so samples touching rest
// are skipped.
std::optional<glm::dvec3> position(const std::vector<TimelineKey>& track, double t) {
    const TimelineSample s = sampleTrack(track, t);
    if (s.from->rest || s.to->rest) return std::nullopt;
    return s.from->pose.positionMm + s.blend * (s.to->pose.positionMm - s.from->pose.positionMm);
}

TEST(Timeline, HandsMoveWithoutJumpsAndStopSmoothlyAtKeys) {
    for (VerbVersion v : kVersions) {
        const Timeline t = buildTimeline(world().story, v, world().sources());
        const double dt = 0.001;
        double fastest = 0.0;
        for (double time = 0.0; time + dt <= t.durationSeconds; time += dt) {
            const auto a = position(t.right, time), b = position(t.right, time + dt);
            if (a && b) fastest = std::max(fastest, glm::length(*b - *a) / dt);
        }
        // Fluent signing peaks near 2-3 m/s; a jump between keys would be far above.
        EXPECT_LT(fastest, 4000.0) << toString(v) << " mm/s";
        // Minimum jerk: zero velocity at every key.
        EXPECT_NEAR(minimumJerk(1e-4) / 1e-4, 0.0, 1e-5);
        EXPECT_NEAR((1.0 - minimumJerk(1.0 - 1e-4)) / 1e-4, 0.0, 1e-5);
    }
}

TEST(Timeline, FingerspelledLettersAreEachHeld) {
    const Timeline t = buildTimeline(world().story, VerbVersion::Point, world().sources());
    const TimelineSpan* ann = nullptr;
    for (const TimelineSpan& s : t.spans)
        if (s.label == "fs-ANN") ann = &s;
    ASSERT_NE(ann, nullptr);
    std::vector<std::string> held;
    for (std::size_t i = 1; i < t.right.size(); ++i) {
        const TimelineKey &a = t.right[i - 1], &b = t.right[i];
        if (a.timeSeconds >= ann->startSeconds - 1e-9 && b.timeSeconds <= ann->endSeconds + 1e-9 && !a.rest &&
            a.handshape == b.handshape && a.pose.positionMm == b.pose.positionMm) {
            held.push_back(a.handshape);
            EXPECT_NEAR(b.timeSeconds - a.timeSeconds, TimelineOptions{}.letterSeconds, 1e-9);
        }
    }
    EXPECT_EQ(held, (std::vector<std::string>{"A", "N", "N"}));
    // The doubled N slides to the signer's right.
    double firstN = 0.0, secondN = 0.0;
    for (const TimelineKey& k : t.right)
        if (k.timeSeconds >= ann->startSeconds && k.timeSeconds <= ann->endSeconds && k.handshape == "N")
            (firstN == 0.0 ? firstN : secondN) = k.pose.positionMm.x, firstN = firstN == 0.0 ? k.pose.positionMm.x : firstN;
    EXPECT_GT(secondN, firstN);
}

TEST(Timeline, GazeFollowsPointingAndTheVerbsObjectAndReturnsToTheViewer) {
    const Timeline t = buildTimeline(world().story, VerbVersion::Vector, world().sources());
    auto targetAt = [&](double time) {
        const GazeSample s = sampleGaze(t.gaze, time);
        return s.blend < 0.5 ? s.from->targetMm : s.to->targetMm;
    };
    int checked = 0;
    for (const TimelineSpan& span : t.spans) {
        const double middle = 0.5 * (span.startSeconds + span.endSeconds) + 0.05;
        if (span.kind == SpanKind::Pointing && span.sentence == 0) {
            ASSERT_TRUE(targetAt(middle));
            EXPECT_NEAR(glm::length(*targetAt(middle) - arcPoint(0.9)), 0.0, 1e-9);
            ++checked;
        }
        if (span.kind == SpanKind::Verb && span.label == "ASK") {
            ASSERT_TRUE(targetAt(middle));
            EXPECT_NEAR(glm::length(*targetAt(middle) - arcPoint(-0.6)), 0.0, 1e-9);
            ++checked;
        }
        if (span.kind == SpanKind::Sign && span.label == "MY") {
            EXPECT_FALSE(targetAt(span.endSeconds - 0.01)) << "looks at the viewer while signing MY";
            ++checked;
        }
    }
    EXPECT_EQ(checked, 4);
}

TEST(Timeline, ASignMissingFromTheLexiconIsNamedAtItsLineAndColumn) {
    Lexicon small = world().lexicon;
    small.signs.erase(small.signs.begin());  // no MY
    TimelineSources sources = world().sources();
    sources.lexicon = &small;
    try {
        buildTimeline(world().story, VerbVersion::Point, sources);
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "test-story.json");
        EXPECT_EQ(e.line(), 5);
        EXPECT_EQ(e.column(), 19);
        EXPECT_NE(std::string(e.what()).find("has no sign MY"), std::string::npos) << e.what();
    }
}

TEST(Timeline, JsonIsTheSameForTheSameInputs) {
    const std::string a = formatTimelineJson(buildTimeline(world().story, VerbVersion::Point, world().sources()));
    const std::string b = formatTimelineJson(buildTimeline(world().story, VerbVersion::Point, world().sources()));
    EXPECT_EQ(a, b);
    EXPECT_EQ(a.find("nan"), std::string::npos);
    EXPECT_NE(a.find("\"kind\": \"verb\""), std::string::npos);
}

// Issue 22: a story at arc positions no animator file covers renders in point, vector and
// uninflected; the animator version names every missing file at once.
TEST(Timeline, MissingAnimatorFilesStopOnlyTheAnimatorVersionAndAreNamedAtOnce) {
    const World& w = world();
    const Story story = parseStory(parseJsonText(R"json({
  "format": "signstim-story", "version": 1, "title": "New places",
  "characters": [{"gloss": "JOHN", "position": 0.5}, {"gloss": "MARY", "position": -0.5}],
  "sentences": [
    "JOHN IX(0.5) ASK MARY IX(-0.5)",
    "IX(MARY) TELL IX(JOHN)",
    "IX(JOHN) ASK IX(MARY)"
  ]
})json", "new-places.json"), StoryVocabulary{&w.verbs, w.lexicon.glosses(), nullptr, nullptr});
    TimelineSources sources = w.sources();
    sources.verbs = [&w](const std::string& verb, VerbVersion version, double subject, double object, int line, int column) {
        try {
            return synthesizeVerb(VerbSources{&w.verbs, &w.models, kSource + "/scenes/animator"}, verb, version, subject, object);
        } catch (const MissingAnimatorFile& e) {
            throw MissingAnimatorFile("new-places.json", line, column, e.what(), e.animatorFile());
        }
    };
    std::vector<double> durations;
    for (VerbVersion v : {VerbVersion::Point, VerbVersion::Vector, VerbVersion::Uninflected})
        durations.push_back(buildTimeline(story, v, sources).durationSeconds);
    EXPECT_DOUBLE_EQ(durations[0], durations[1]);
    EXPECT_DOUBLE_EQ(durations[0], durations[2]);
    try {
        buildTimeline(story, VerbVersion::Animator, sources);
        FAIL() << "the animator version built without its files";
    } catch (const MissingAnimatorFiles& e) {
        EXPECT_EQ(e.file(), "new-places.json");
        EXPECT_EQ(e.line(), 5) << "the first verb that needs one";
        ASSERT_EQ(e.files().size(), 2u) << "ASK at (0.5, -0.5) once, TELL at -0.5 -> 0.5";
        EXPECT_NE(e.files()[0].find("ASK_s0.5_o-0.5.json"), std::string::npos) << e.files()[0];
        EXPECT_NE(e.files()[1].find("TELL_o0.5.json"), std::string::npos) << e.files()[1];
        const std::string message = e.what();
        EXPECT_NE(message.find("ASK_s0.5_o-0.5.json"), std::string::npos) << message;
        EXPECT_NE(message.find("TELL_o0.5.json"), std::string::npos) << message;
        EXPECT_NE(message.find("signstim animator draft"), std::string::npos) << message;
    }
}

std::string replacedOnce(std::string text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

// `signstim animator draft` writes the point model's keyframes marked "draft": true; read back,
// the file is a draft with the point model's keyframes. Without its mark it is the copied draft
// story --check warns about; edited, it is an animator's own work.
TEST(AnimatorDraft, ADraftIsThePointModelMarkedAndAnUnmarkedCopyIsRecognised) {
    const World& w = world();
    const VerbSources sources{&w.verbs, &w.models, kSource + "/scenes/animator", &w.shapes};
    const VerbDefinition& ask = *w.verbs.find("ASK");
    const std::string text = formatAnimatorDraft(sources, "ASK", 0.5, -0.5);
    EXPECT_NE(text.find("\"draft\": true"), std::string::npos) << text;
    const VerbPerformance point = synthesizeVerb(sources, "ASK", VerbVersion::Point, 0.5, -0.5);
    const VerbPerformance draft = parseAnimatorPerformance(parseJsonText(text, "ASK_s0.5_o-0.5.json"), ask, 0.5, -0.5);
    EXPECT_TRUE(draft.draft);
    EXPECT_TRUE(sameKeyframes(draft, point));

    const std::string unmarked = replacedOnce(text, "\"draft\": true", "\"draft\": false");
    const VerbPerformance copied = parseAnimatorPerformance(parseJsonText(unmarked, "ASK_s0.5_o-0.5.json"), ask, 0.5, -0.5);
    EXPECT_FALSE(copied.draft);
    EXPECT_TRUE(sameKeyframes(copied, point)) << "a copied draft is recognised";

    VerbPerformance edited = copied;
    edited.hands[0].keyframes[1].pose.positionMm.x += 5.0;
    EXPECT_FALSE(sameKeyframes(edited, point)) << "an animator's edit is not a draft";
    edited = copied;
    edited.hands[0].keyframes[0].handshape = "X";
    EXPECT_FALSE(sameKeyframes(edited, point));

    const std::string bad = replacedOnce(text, "\"draft\": true", "\"draft\": \"yes\"");
    try {
        parseAnimatorPerformance(parseJsonText(bad, "ASK_s0.5_o-0.5.json"), ask, 0.5, -0.5);
        FAIL() << "\"draft\": \"yes\" accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(e.file(), "ASK_s0.5_o-0.5.json");
        EXPECT_EQ(e.field(), "/draft");
        EXPECT_GT(e.line(), 1);
        EXPECT_NE(std::string(e.what()).find("expected true"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace signstim::stimuli

// Issue 23: a non-manual channel is 0 outside its keys, passes through each key's value and
// eases monotonically between two keys (minimum jerk), whatever the sampling instants.
TEST(NonManualSampling, ZeroOutsideKeysExactAtKeysMonotoneBetween) {
    signstim::stimuli::NonManualTrack track{"browInnerUp", {{1.0, 0.0}, {1.2, 0.8}, {2.0, 0.8}, {2.3, 0.0}}};
    using signstim::stimuli::sampleNonManual;
    EXPECT_EQ(sampleNonManual(track, 0.5), 0.0);
    EXPECT_EQ(sampleNonManual(track, 2.31), 0.0);
    EXPECT_DOUBLE_EQ(sampleNonManual(track, 1.2), 0.8);
    EXPECT_DOUBLE_EQ(sampleNonManual(track, 1.6), 0.8);
    EXPECT_DOUBLE_EQ(sampleNonManual(track, 2.0), 0.8);
    double previous = 0.0;
    for (double t = 1.0; t <= 1.2; t += 0.01) {
        const double v = sampleNonManual(track, t);
        EXPECT_GE(v, previous - 1e-12);
        previous = v;
    }
    EXPECT_NEAR(sampleNonManual(track, 1.1), 0.4, 1e-12);  // minimum jerk is symmetric about u = 1/2
    signstim::stimuli::Timeline timeline;
    timeline.nonManuals.push_back(track);
    ASSERT_NE(signstim::stimuli::findNonManual(timeline, "browInnerUp"), nullptr);
    EXPECT_EQ(signstim::stimuli::findNonManual(timeline, "jawOpen"), nullptr);
}
