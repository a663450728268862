// Fuzz targets of the data files a researcher edits or brings (scenes/ and the command line):
// handshapes, verbs, animator keyframes, verb models, the reference performer, the corpus CSV,
// sensor samples and calibration, lexicon, gloss sentences, stories, study files and the
// study listing a study's plan.json and manifest.json carry.
#include "common/error.hpp"
#include "stimuli/verbs/corpus.hpp"
#include "stimuli/story/gloss.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/verbs/reference_performer.hpp"
#include "stimuli/verbs/sensor_io.hpp"
#include "stimuli/study/study.hpp"
#include "stimuli/verbs/verb_models.hpp"
#include "stimuli/verbs/verb_synthesis.hpp"
#include "tests/fuzz/fixtures.hpp"
#include "tests/fuzz/fuzz_target.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace signstim::fuzz {
namespace {

using namespace signstim::stimuli;

void requireFinitePose(const HandPose& pose) {
    for (int i = 0; i < 3; ++i) requireFinite(pose.positionMm[i], "position");
    for (int i = 0; i < 4; ++i) requireFinite(pose.orientation[i], "orientation");
}

// The shared JSON reader (parse errors, duplicate keys, a byte-order mark), then `read`.
template <class Read>
void jsonFile(std::string_view input, const char* name, Read&& read) {
    expectRefusalOrSuccess(name, [&] {
        const JsonSource source = parseJsonText(std::string(input), name);
        read(source);
    });
}

}  // namespace
}  // namespace signstim::fuzz

using namespace signstim;
using namespace signstim::stimuli;
using signstim::fuzz::expectRefusalOrSuccess;
using signstim::fuzz::requireFinite;

SIGNSTIM_FUZZ_TARGET(handshapes) {
    expectRefusalOrSuccess("handshapes.json", [&] {
        const HandshapeLibrary library = parseHandshapes(std::string(input), "handshapes.json", fuzz::handModel());
        for (const Handshape& shape : library.shapes) {
            requireFinite(shape.controls.thumb.bendDeg, "thumb bend");
            for (const auto& finger : shape.controls.fingers) requireFinite(finger.bend, "finger bend");
        }
    });
}

SIGNSTIM_FUZZ_TARGET(verbs) {
    fuzz::jsonFile(input, "verbs.json", [](const JsonSource& source) {
        const VerbLibrary library = parseVerbLibrary(source);
        for (const VerbDefinition& verb : library.verbs)
            for (const auto& hand : verb.citation)
                for (const VerbKeyframe& keyframe : hand) {
                    requireFinite(keyframe.timeSeconds, "keyframe time");
                    fuzz::requireFinitePose(keyframe.pose);
                }
    });
}

// The file names its verb, subject and object, which must match what the command asked for:
// take them from the input when they are usable, so the fuzzer gets past that check.
SIGNSTIM_FUZZ_TARGET(animator) {
    const nlohmann::json peek = nlohmann::json::parse(input, nullptr, false);
    const VerbDefinition* verb = &fuzz::verbs().verbs.front();
    double subject = 0.9, object = -0.6;
    if (peek.is_object()) {
        if (auto v = peek.find("verb"); v != peek.end() && v->is_string())
            if (const VerbDefinition* named = fuzz::verbs().find(v->get<std::string>())) verb = named;
        if (auto s = peek.find("subject"); s != peek.end() && s->is_number()) subject = s->get<double>();
        if (auto o = peek.find("object"); o != peek.end() && o->is_number()) object = o->get<double>();
    }
    fuzz::jsonFile(input, "ASK_s0.9_o-0.6.json", [&](const JsonSource& source) {
        const VerbPerformance performance = parseAnimatorPerformance(source, *verb, subject, object);
        requireFinite(performance.durationSeconds, "duration");
    });
}

// Accepted models are also evaluated (what `verb --version point|vector` does next): an
// accepted file must not predict a non-finite hand. One verb per input (chosen by its size),
// as prediction costs four fifths of an execution.
SIGNSTIM_FUZZ_TARGET(verb_models) {
    fuzz::jsonFile(input, "verb_models.json", [&](const JsonSource& source) {
        const TrainedVerbModels models = parseVerbModels(source, fuzz::verbs());
        if (models.verbs.empty()) return;
        const VerbModel& model = models.verbs[input.size() % models.verbs.size()];
        for (const auto& predict : {predictPoint, predictVector})
            for (const auto& hand : predict(model, 0.9, -0.6))
                for (const HandPose& pose : hand) fuzz::requireFinitePose(pose);
    });
}

SIGNSTIM_FUZZ_TARGET(reference_performer) {
    fuzz::jsonFile(input, "reference_performer.json",
                   [](const JsonSource& source) { parseReferencePerformer(source, fuzz::verbs()); });
}

SIGNSTIM_FUZZ_TARGET(corpus_csv) {
    expectRefusalOrSuccess("corpus.csv", [&] {
        const Corpus corpus = parseCorpus(input, "corpus.csv", fuzz::verbs());
        for (const CorpusExample& example : corpus.examples) {
            requireFinite(example.subject, "subject");
            requireFinite(example.object, "object");
            for (const auto& hand : example.poses)
                for (const HandPose& pose : hand) fuzz::requireFinitePose(pose);
        }
    });
}

SIGNSTIM_FUZZ_TARGET(sensor_csv) {
    expectRefusalOrSuccess("samples.csv", [&] {
        for (const SensorSample& sample : parseSensorSamples(std::string(input), "samples.csv")) {
            requireFinite(sample.timeS, "time");
            for (const auto& reading : sample.readings) {
                for (int i = 0; i < 3; ++i) requireFinite(reading.positionMm[i], "sensor position");
                requireFinite(reading.azimuthDeg, "azimuth");
                requireFinite(reading.elevationDeg, "elevation");
                requireFinite(reading.rollDeg, "roll");
            }
        }
    });
}

SIGNSTIM_FUZZ_TARGET(calibration) {
    expectRefusalOrSuccess("calibration.json", [&] {
        const hand::SensorCalibration cal = parseSensorCalibration(std::string(input), "calibration.json");
        requireFinite(cal.handThicknessMm, "hand thickness");
        for (const auto& digit : cal.digits)
            for (float length : digit.lengthMm) requireFinite(length, "phalanx length");
    });
}

SIGNSTIM_FUZZ_TARGET(lexicon) {
    fuzz::jsonFile(input, "signs.json", [](const JsonSource& source) {
        parseLexicon(source, fuzz::handshapes(), fuzz::handModel());
    });
}

// One sentence. Errors are values here (a column and a message), checked to point into it.
SIGNSTIM_FUZZ_TARGET(gloss) {
    const GlossParse parse = parseGloss(input);
    if (parse.error) {
        if (parse.error->column < 1 || static_cast<std::size_t>(parse.error->column) > input.size() + 1)
            fuzz::fail("a gloss error at column " + std::to_string(parse.error->column) + " of a " +
                       std::to_string(input.size()) + "-byte sentence");
        if (parse.error->message.empty()) fuzz::fail("a gloss error without a message");
        return;
    }
    for (const GlossItem& item : parse.items) {
        if (item.column < 1 || static_cast<std::size_t>(item.column) > input.size())
            fuzz::fail("an item at column " + std::to_string(item.column));
        if (item.holdSeconds) requireFinite(*item.holdSeconds, "hold");
        for (const GlossArgument& argument : item.arguments)
            if (argument.position) requireFinite(*argument.position, "position");
    }
    // Non-manual markers (docs/nonmanuals.md): inside the sentence, over items that exist.
    for (const GlossMarker& marker : parse.markers) {
        if (marker.column < 1 || static_cast<std::size_t>(marker.column) > input.size())
            fuzz::fail("a marker at column " + std::to_string(marker.column));
        const int items = static_cast<int>(parse.items.size());
        if (marker.firstItem < 0 || marker.firstItem > items || marker.lastItem >= items ||
            (!marker.event() && marker.lastItem < marker.firstItem))
            fuzz::fail("a marker over items " + std::to_string(marker.firstItem) + ".." + std::to_string(marker.lastItem));
        if (marker.intensity && !(*marker.intensity >= 0.1 && *marker.intensity <= 1.5))
            fuzz::fail("a marker's intensity outside 0.1 to 1.5");
    }
}

SIGNSTIM_FUZZ_TARGET(story) {
    fuzz::jsonFile(input, "story.json", [](const JsonSource& source) {
        const Story story = parseStory(source, fuzz::storyVocabulary());
        for (const StoryCharacter& character : story.characters) requireFinite(character.position, "position");
    });
}

SIGNSTIM_FUZZ_TARGET(study) {
    fuzz::jsonFile(input, "study.json", [](const JsonSource& source) { parseStudyFile(source); });
}

// The listing inside plan.json / manifest.json ("listing"), which `study merge`, `study
// verify` and `analyze` read back.
SIGNSTIM_FUZZ_TARGET(study_listing) {
    fuzz::jsonFile(input, "plan.json", [](const JsonSource& source) {
        withJsonErrors(source, [&] { return listingFromJson(source.root, "plan.json"); });
    });
}
