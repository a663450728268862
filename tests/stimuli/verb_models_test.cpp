// Verb data, the corpus format, the reference performer and the trained models
// (SPEC §3.2–§3.8).
#include "common/error.hpp"
#include "hand/hand_model.hpp"
#include "stimuli/verbs/corpus.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/verbs/reference_performer.hpp"
#include "stimuli/verbs/signing_space.hpp"
#include "stimuli/verbs/sora.hpp"
#include "stimuli/verbs/verb_models.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <numbers>

namespace signstim::stimuli {
namespace {

const std::filesystem::path kScenes = std::filesystem::path(SIGNSTIM_SOURCE_DIR) / "scenes";

const VerbLibrary& library() {
    static const VerbLibrary verbs = loadVerbLibrary(kScenes / "verbs.json");
    return verbs;
}
const Corpus& referenceCorpus() {
    static const Corpus corpus = loadCorpus(kScenes / "corpus" / "reference_corpus.csv", library());
    return corpus;
}
const TrainedVerbModels& shippedModels() {
    static const TrainedVerbModels models = loadVerbModels(kScenes / "models" / "verb_models.json", library());
    return models;
}

const std::string kHeader = "verb,example,subject,object,hand,keyframe,x,y,z,roll,pitch,yaw\n";

int errorLine(const std::string& csv) {
    try {
        parseCorpus(csv, "bad.csv", library());
    } catch (const InputError& e) {
        return e.line();
    }
    return -1;
}

std::string askRow(int example, int keyframe, const std::string& x = "10") {
    return "ASK," + std::to_string(example) + ",0.3,-0.6,right," + std::to_string(keyframe) + "," + x + ",2,3,0,0,0\n";
}

TEST(VerbLibrary, HasTheEightVerbsOfThePaperWithTheirClassAndHands) {
    const VerbLibrary& verbs = library();
    ASSERT_EQ(verbs.verbs.size(), 8u);
    const std::vector<std::tuple<std::string, Inflection, std::size_t>> expected{
        {"ASK", Inflection::SubjectObject, 1},  {"GIVE", Inflection::SubjectObject, 2},
        {"MEET", Inflection::SubjectObject, 2}, {"SCOLD", Inflection::ObjectOnly, 1},
        {"TELL", Inflection::ObjectOnly, 1},    {"COPY", Inflection::SubjectObject, 2},
        {"EMAIL", Inflection::SubjectObject, 2}, {"SEND", Inflection::SubjectObject, 2}};
    for (const auto& [name, inflection, hands] : expected) {
        const VerbDefinition* verb = verbs.find(name);
        ASSERT_NE(verb, nullptr) << name;
        EXPECT_EQ(verb->inflection, inflection) << name;
        EXPECT_EQ(verb->handCount(), hands) << name;
        // EMAIL: the swing from the subject, the index's aim at the C, its slide in and back out;
        // COPY: the touch on the base palm, the lift off it, the closing hand's pull away.
        EXPECT_EQ(verb->keyframeCount(), name == "EMAIL" ? 4u : name == "COPY" ? 3u : 2u) << name;
    }
    EXPECT_EQ(verbs.find("ASK")->citation[0][0].handshape, "1");
    EXPECT_EQ(verbs.find("ASK")->citation[0][1].handshape, "X");  // the index finger bends
    EXPECT_EQ(verbs.find("EMAIL")->citation[0][0].handshape, "1");  // ASL-LEX 2.0 'email': 1 on a C base
    EXPECT_EQ(verbs.find("EMAIL")->citation[1][0].handshape, "C");
}

TEST(VerbLibrary, EveryHandshapeNameIsInTheHandshapeLibrary) {
    const HandshapeLibrary shapes = loadHandshapes(kScenes / "handshapes.json", hand::buildHandModel());
    EXPECT_NO_THROW(checkHandshapeNames(library(), [&](const std::string& name) { return shapes.find(name) != nullptr; }));
    EXPECT_THROW(checkHandshapeNames(library(), [](const std::string& name) { return name != "C"; }), InputError);
}

TEST(VerbLibrary, UnknownVerbListsTheKnownOnes) {
    try {
        library().get("HUG");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("ASK, GIVE, MEET, SCOLD, TELL, COPY, EMAIL, SEND"), std::string::npos);
    }
}

TEST(VerbLibrary, MalformedFilesNameTheLineAndField) {
    const std::string text =
        "{\n \"verbs\": [\n  {\n   \"name\": \"ASK\",\n   \"inflects\": \"subject-object\",\n"
        "   \"hands\": [\"right\"],\n   \"citation\": {\n    \"right\": [\n"
        "     {\"time\": 0, \"position\": [0, 0, 1], \"fingers\": [0, 1, 0], \"palm\": [0, 0, 1], \"handshape\": \"1\"},\n"
        "     {\"time\": 0.5, \"position\": [0, \"x\", 1], \"fingers\": [0, 1, 0], \"palm\": [0, 0, 1], \"handshape\": \"X\"}\n"
        "    ]\n   }\n  }\n ]\n}\n";
    try {
        parseVerbLibrary(parseJsonText(text, "verbs.json"));
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 10);
        EXPECT_EQ(e.field(), "/verbs/0/citation/right/1/position");
    }
    try {
        parseJsonText("{\n \"verbs\": [\n ,\n]}", "verbs.json");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 3);
    }
}

TEST(Corpus, ReferenceCorpusHas42ExamplesPerVerbAndSaysItIsSynthetic) {
    const Corpus& corpus = referenceCorpus();
    ASSERT_FALSE(corpus.comments.empty());
    EXPECT_NE(corpus.comments.front().find("SYNTHETIC"), std::string::npos);
    for (const VerbDefinition& verb : library().verbs) {
        const auto examples = corpus.examplesOf(verb.name);
        EXPECT_EQ(examples.size(), 42u) << verb.name;
        std::set<std::pair<double, double>> arrangements;
        for (const CorpusExample* e : examples) {
            EXPECT_NE(e->subject, e->object);
            arrangements.insert({e->subject, e->object});
        }
        EXPECT_EQ(arrangements.size(), 42u) << verb.name;  // 7 positions × 6 others
    }
}

TEST(Corpus, TheReferencePerformerReproducesTheShippedCorpusByteForByte) {
    const ReferencePerformer performer = loadReferencePerformer(kScenes / "corpus" / "reference_performer.json", library());
    const std::string generated = formatCorpus(generateReferenceCorpus(performer, library()), library());
    EXPECT_EQ(generated, readTextFile(kScenes / "corpus" / "reference_corpus.csv"));
}

TEST(Corpus, WritingAndReadingBackKeepsEveryValueToItsPrintedPrecision) {
    const Corpus& corpus = referenceCorpus();
    const Corpus again = parseCorpus(formatCorpus(corpus, library()), "again.csv", library());
    ASSERT_EQ(again.examples.size(), corpus.examples.size());
    for (std::size_t i = 0; i < corpus.examples.size(); ++i)
        for (std::size_t h = 0; h < corpus.examples[i].poses.size(); ++h)
            for (std::size_t k = 0; k < corpus.examples[i].poses[h].size(); ++k) {
                EXPECT_LT(glm::length(again.examples[i].poses[h][k].positionMm - corpus.examples[i].poses[h][k].positionMm), 0.01);
                EXPECT_LT(rotationAngleBetween(again.examples[i].poses[h][k].orientation,
                                               corpus.examples[i].poses[h][k].orientation), 1e-4);
            }
}

TEST(Corpus, ColumnsMayComeInAnyOrderWithExtraColumns) {
    const std::string csv = "# lab export\nhand,keyframe,verb,example,object,subject,x,y,z,yaw,pitch,roll,take\n"
                            "right,0,ASK,1,-0.6,0.3,1,2,3,0,0,0,t1\nright,1,ASK,1,-0.6,0.3,4,5,6,90,0,0,t1\n";
    const Corpus corpus = parseCorpus(csv, "lab.csv", library());
    ASSERT_EQ(corpus.examples.size(), 1u);
    EXPECT_EQ(corpus.examples[0].subject, 0.3);
    EXPECT_EQ(corpus.examples[0].poses[0][1].positionMm, glm::dvec3(4, 5, 6));
    EXPECT_LT(rotationAngleBetween(corpus.examples[0].poses[0][1].orientation, rollPitchYawDegreesToQuaternion(0, 0, 90)), 1e-12);
}

TEST(Corpus, MalformedRowsAreErrorsWithTheirLine) {
    EXPECT_EQ(errorLine(kHeader + askRow(1, 0) + "ASK,1,0.3,-0.6,right,1,10,2\n"), 3);        // missing fields
    EXPECT_EQ(errorLine(kHeader + askRow(1, 0) + "ASK,1,0.3,-0.6,right,1,,2,3,0,0,0\n"), 3);  // empty value
    EXPECT_EQ(errorLine(kHeader + askRow(1, 0) + askRow(1, 1) + askRow(1, 0)), 4);           // duplicate
    EXPECT_EQ(errorLine(kHeader + askRow(1, 0) + askRow(1, 1, "ten")), 3);                   // non-numeric
    EXPECT_EQ(errorLine(kHeader + askRow(1, 0) + "HUG,1,0.3,-0.6,right,0,1,2,3,0,0,0\n"), 3); // unknown verb
    EXPECT_EQ(errorLine(kHeader + "ASK,1,0.3,-1.6,right,0,1,2,3,0,0,0\n"), 2);               // off the arc
    EXPECT_EQ(errorLine(kHeader + "ASK,1,0.3,-0.6,left,0,1,2,3,0,0,0\n"), 2);                // one-handed verb
    EXPECT_EQ(errorLine(kHeader + "ASK,1,0.3,-0.6,right,2,1,2,3,0,0,0\n"), 2);               // no such keyframe
    EXPECT_EQ(errorLine("# c\n" + kHeader + askRow(1, 0)), 3);                               // keyframe 1 missing
    EXPECT_EQ(errorLine(kHeader + askRow(1, 0) + "ASK,1,0.6,-0.6,right,1,1,2,3,0,0,0\n"), 3); // subject changes
    EXPECT_EQ(errorLine("verb,example,subject\nASK,1,0.3\n"), 1);                             // header lacks columns
}

TEST(PointModel, ReproducesTheNoiseFreePerformerWithinTheNoise) {
    const ReferencePerformer performer = loadReferencePerformer(kScenes / "corpus" / "reference_performer.json", library());
    for (const VerbDefinition& verb : library().verbs) {
        const VerbModel& model = *shippedModels().find(verb.name);
        double positionError = 0.0, orientationError = 0.0, residual = 0.0;
        int count = 0;
        for (const CorpusExample* e : referenceCorpus().examplesOf(verb.name)) {
            const auto predicted = predictPoint(model, e->subject, e->object);
            const auto clean = performVerb(performer, verb, e->subject, e->object);
            for (std::size_t h = 0; h < verb.handCount(); ++h)
                for (std::size_t k = 0; k < verb.keyframeCount(); ++k) {
                    // The clean performance with the performer's bias but without noise.
                    const glm::dvec3 biased = performer.torsoPivotMm +
                                              performer.biasReachGain * (clean[h][k].positionMm - performer.torsoPivotMm) +
                                              performer.biasOffsetMm;
                    positionError += glm::length(predicted[h][k].positionMm - biased);
                    residual += glm::length(predicted[h][k].positionMm - e->poses[h][k].positionMm);
                    const glm::dquat yaw(std::cos(0.5 * performer.biasYawDeg * std::numbers::pi / 180), 0,
                                         std::sin(0.5 * performer.biasYawDeg * std::numbers::pi / 180), 0);
                    orientationError += rotationAngleBetween(predicted[h][k].orientation, yaw * clean[h][k].orientation);
                    ++count;
                }
        }
        // Noise: 5 mm per axis (|n| ≈ 8 mm) and 2° per axis.
        EXPECT_LT(positionError / count, 5.0) << verb.name;
        EXPECT_LT(residual / count, 9.0) << verb.name;
        EXPECT_LT(orientationError / count * 180 / std::numbers::pi, 2.5) << verb.name;
    }
}

TEST(VerbModels, TrainingTheShippedCorpusReproducesTheShippedModelsByteForByte) {
    const std::string trained = formatVerbModels(trainVerbModels(referenceCorpus(), library()));
    EXPECT_EQ(trained, readTextFile(kScenes / "models" / "verb_models.json"));
    // And the JSON reads back to the same predictions.
    const TrainedVerbModels again = parseVerbModels(parseJsonText(trained, "m.json"), library());
    const auto a = predictPoint(*again.find("GIVE"), 0.9, -0.6);
    const auto b = predictPoint(*shippedModels().find("GIVE"), 0.9, -0.6);
    EXPECT_EQ(a[1][1].positionMm, b[1][1].positionMm);
}

TEST(VerbModels, ObjectOnlyVerbsIgnoreTheSubject) {
    for (const char* name : {"SCOLD", "TELL"}) {
        const VerbModel& model = *shippedModels().find(name);
        for (const auto predict : {&predictPoint, &predictVector}) {
            const auto a = predict(model, -0.9, 0.3);
            const auto b = predict(model, 0.6, 0.3);
            for (std::size_t k = 0; k < model.keyframes; ++k) {
                EXPECT_EQ(a[0][k].positionMm, b[0][k].positionMm) << name;
                EXPECT_EQ(a[0][k].orientation, b[0][k].orientation) << name;
            }
        }
        // ... but follow the object.
        EXPECT_GT(glm::length(predictPoint(model, 0, 0.9)[0][1].positionMm - predictPoint(model, 0, -0.9)[0][1].positionMm), 100.0);
    }
}

TEST(VerbModels, SwappingSubjectAndObjectReversesThePathDirection) {
    // Path from subject toward object (COPY: from the object toward the subject).
    for (const char* name : {"ASK", "GIVE", "EMAIL", "SEND", "COPY"}) {
        const VerbModel& model = *shippedModels().find(name);
        const double sign = std::string(name) == "COPY" ? -1.0 : 1.0;
        for (const auto predict : {&predictPoint, &predictVector}) {
            const auto forward = predict(model, 0.9, -0.6);
            const auto backward = predict(model, -0.6, 0.9);
            // From the first key to the last (COPY lifts off the palm on the way).
            const glm::dvec3 d1 = forward[0].back().positionMm - forward[0].front().positionMm;
            const glm::dvec3 d2 = backward[0].back().positionMm - backward[0].front().positionMm;
            EXPECT_LT(sign * d1.x, -100.0) << name;  // toward the object on the left
            EXPECT_GT(sign * d2.x, 100.0) << name;
            // The sideways part reverses; the outward (+z) part of signing away from the body
            // stays, and the right hand's own offset from the midline makes the two unequal.
        }
    }
}

TEST(VectorModel, TheStartRunsThroughTheMostLikelyRegionAndKeepsTheHandsTogether) {
    const VerbModel& model = *shippedModels().find("EMAIL");
    const auto poses = predictVector(model, 0.9, -0.6);
    const glm::dvec3 start = poses[0][0].positionMm;
    // Every keyframe of the path (EMAIL's four: swing, aim, slide in, back out).
    std::vector<glm::dvec3> offsets;
    for (const HandPose& key : poses[0]) offsets.push_back(key.positionMm - start);
    const auto score = [&](const glm::dvec3& p) {
        std::vector<glm::dvec3> path;
        for (const glm::dvec3& offset : offsets) path.push_back(p + offset);
        return model.vector.rightLocation.sumLogDensity(pathSamples(path));
    };
    for (const glm::dvec3& step : {glm::dvec3(5, 0, 0), glm::dvec3(0, 5, 0), glm::dvec3(0, 0, 5)}) {
        EXPECT_GE(score(start), score(start + step));
        EXPECT_GE(score(start), score(start - step));
    }
    // The left hand is placed relative to the right one (SPEC §3.5).
    for (std::size_t k = 0; k < poses[0].size(); ++k)
        EXPECT_LT(glm::length(poses[1][k].positionMm - poses[0][k].positionMm - model.vector.leftRelative[k](0.9, -0.6)), 1e-9);
    EXPECT_GE(model.vector.rightLocation.components.size(), 1u);
}

TEST(VerbSynthesis, UninflectedIsTheSameForEverySubjectAndObject) {
    const VerbSources sources{&library(), &shippedModels(), kScenes / "animator"};
    const std::string a = formatPerformanceJson(synthesizeVerb(sources, "GIVE", VerbVersion::Uninflected, 0.9, -0.6));
    const std::string b = formatPerformanceJson(synthesizeVerb(sources, "GIVE", VerbVersion::Uninflected, -0.3, 0.6));
    EXPECT_EQ(a.substr(a.find("\"hands\"")), b.substr(b.find("\"hands\"")));
}

TEST(VerbSynthesis, PositionsOffTheArcAreErrorsNamingTheFlag) {
    const VerbSources sources{&library(), &shippedModels(), kScenes / "animator"};
    try {
        synthesizeVerb(sources, "ASK", VerbVersion::Point, 1.2, 0.0);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.field(), "--subject");
    }
    EXPECT_NO_THROW(synthesizeVerb(sources, "TELL", VerbVersion::Point, 7.0, 0.0));  // subject ignored
}

TEST(VerbSynthesis, ScoldWagsForthAndBack) {
    const VerbSources sources{&library(), &shippedModels(), kScenes / "animator"};
    const VerbPerformance p = synthesizeVerb(sources, "SCOLD", VerbVersion::Point, 0, -0.6);
    ASSERT_EQ(p.hands[0].keyframes.size(), 4u);  // 3 passes: 0→1→0→1
    EXPECT_EQ(p.hands[0].keyframes[0].pose.positionMm, p.hands[0].keyframes[2].pose.positionMm);
    EXPECT_NEAR(p.durationSeconds, 3 * 0.18, 1e-12);
    const HandSample middle = sampleHand(p.hands[0], 0.09);
    EXPECT_NEAR(middle.handshapeBlend, 0.5, 1e-12);
}

TEST(Animator, PointJsonIsAValidAnimatorFileAndMissingFilesNameTheFileToAuthor) {
    const VerbSources sources{&library(), &shippedModels(), kScenes / "animator"};
    const VerbPerformance point = synthesizeVerb(sources, "EMAIL", VerbVersion::Point, 0.3, -0.9);
    const std::filesystem::path dir = std::filesystem::path(SIGNSTIM_BINARY_DIR) / "verb_animator_test";
    std::filesystem::create_directories(dir);
    const std::filesystem::path file = dir / animatorFileName(*library().find("EMAIL"), 0.3, -0.9);
    EXPECT_EQ(file.filename(), "EMAIL_s0.3_o-0.9.json");
    {
        std::ofstream out(file);
        out << formatPerformanceJson(point);
    }
    const VerbSources fromDir{&library(), &shippedModels(), dir};
    const VerbPerformance loaded = synthesizeVerb(fromDir, "EMAIL", VerbVersion::Animator, 0.3, -0.9);
    ASSERT_EQ(loaded.hands.size(), 2u);
    for (std::size_t h = 0; h < 2; ++h)
        for (std::size_t k = 0; k < 2; ++k) {
            EXPECT_LT(glm::length(loaded.hands[h].keyframes[k].pose.positionMm - point.hands[h].keyframes[k].pose.positionMm), 0.01);
            EXPECT_LT(rotationAngleBetween(loaded.hands[h].keyframes[k].pose.orientation, point.hands[h].keyframes[k].pose.orientation), 1e-5);
            EXPECT_EQ(loaded.hands[h].keyframes[k].handshape, point.hands[h].keyframes[k].handshape);
        }
    try {
        synthesizeVerb(fromDir, "EMAIL", VerbVersion::Animator, 0.6, -0.9);
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(e.file().find("EMAIL_s0.6_o-0.9.json"), std::string::npos);
        EXPECT_NE(std::string(e.what()).find("author"), std::string::npos);
    }
    EXPECT_EQ(animatorFileName(*library().find("TELL"), 0.5, 0.9), "TELL_o0.9.json");
}

}  // namespace
}  // namespace signstim::stimuli
