#include "tests/stimuli/review_page_fixture.hpp"

#include "stimuli/study/study.hpp"
#include "stimuli/study/study_design.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace signstim::stimuli::testing {
namespace {

std::string twoDigits(std::size_t n) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%02zu", n);
    return buffer;
}

ListedClip clip(const std::string& name, double seconds, bool withFrames) {
    ListedClip c;
    c.video = "clips/" + name + ".mp4";
    c.poster = "posters/" + name + ".png";
    if (withFrames) c.frames = "frames/" + name;
    c.frameCount = static_cast<std::uint64_t>(std::llround(seconds * reviewFixtureFps));
    c.durationSeconds = static_cast<double>(c.frameCount) / reviewFixtureFps;
    return c;
}

const char* const names[] = {"JOHN", "MARY", "BOB", "ANN", "LISA", "TOM"};
const char* const verbs[] = {"ASK", "GIVE", "SEND", "TELL", "COPY", "MEET", "EMAIL", "SCOLD"};
const char* const positions[] = {"0.9", "-0.6", "0.3", "-0.3"};

}  // namespace

double reviewFixtureSeconds(std::size_t version) {
    return 2.0 - 0.2 * static_cast<double>(version % 4);
}

StudyListing reviewFixtureListing(const ReviewFixtureShape& shape) {
    StudyListing listing;
    listing.title = "Verb inflection study <fixture> & \"review\"";
    listing.studyFile = "studies/fixture's study.json";
    listing.toolVersion = "0.4.0";
    listing.seed = 20151;
    listing.designHash = "5f0c9a7e2b64d1038e7a9c2f41d6b0e3a8c5f7d9e1b2a4c6d8e0f1a3b5c7d9e2";
    listing.versions = {"point", "vector", "animator", "uninflected"};
    listing.versionLetters = {"P", "V", "A", "U"};
    listing.size = "160x120";
    listing.fps = "15";
    listing.msaa = 4;

    for (std::size_t s = 0; s < shape.stories; ++s) {
        ListedStory story;
        story.id = "story-" + twoDigits(s + 1);
        story.title = s == 0 ? "Who copied whose homework? <& friends>" : "Story " + std::to_string(s + 1) + ": the 'office' party";
        story.file = "stories/" + story.id + ".json";
        const std::string a = names[s % 6], b = names[(s + 1) % 6], c = names[(s + 2) % 6];
        for (std::size_t k = 0; k < 3; ++k) {
            const std::string verb = verbs[(s + k) % 8];
            story.sentences.push_back(a + " IX(" + positions[k % 4] + ") " + verb + " " + (k % 2 ? c : b) + " IX(" +
                                      positions[(k + 1) % 4] + ")");
        }
        for (std::size_t q = 0; q < 4; ++q) {
            ListedQuestion question;
            const std::string verb = verbs[(s + q) % 8];
            question.text = "Who did the " + verb + " in sentence " + std::to_string(q % 3 + 1) + " go to & from?";
            question.choices = {a + " to " + b, b + " to " + a, c + " to <nobody>"};
            if (q % 2 == 0) question.choices.push_back("\"don't know\"");
            question.answer = static_cast<int>((s + q) % 3);
            question.probeVerb = verb;
            question.probeSentence = static_cast<int>(q % 3);
            if (shape.signedQuestions) {
                question.gloss = std::string(a) + " " + verb + " WHO";
                question.clip = clip(story.id + "_question-" + std::to_string(q + 1), reviewFixtureSignedSeconds,
                                     shape.withFrameFolders);
            }
            story.questions.push_back(question);
        }
        for (std::size_t v = 0; v < listing.versions.size(); ++v)
            story.clips.push_back(clip(story.id + "_version-" + listing.versions[v], reviewFixtureSeconds(v),
                                       shape.withFrameFolders));
        listing.stories.push_back(story);
    }

    StudyDesignSpec spec;
    spec.stories = shape.stories;
    spec.versions = listing.versions.size();
    spec.participants = shape.participants;
    spec.likertTrials = shape.likertSentences;
    spec.seed = listing.seed;

    for (std::size_t s = 0; s < shape.likertSentences; ++s) {
        ListedSentence sentence;
        sentence.id = "likert-" + twoDigits(s + 1);
        sentence.verb = verbs[s % 8];
        sentence.gloss = std::string(names[s % 6]) + " IX(0.9) " + sentence.verb + " " + names[(s + 1) % 6] + " IX(-0.6)";
        sentence.panelVersion = likertPanels(spec, s);
        for (const std::size_t v : sentence.panelVersion) sentence.panelCode += listing.versionLetters[v];
        sentence.clip = clip(sentence.id + "_panels-" + sentence.panelCode, reviewFixtureLikertSeconds,
                             shape.withFrameFolders);
        listing.sentences.push_back(sentence);
    }

    // The experiment's session settings, as a study file without "session" gives them.
    listing.ratingPrompt = std::string(kDefaultRatingPrompt);
    listing.background.assign(kBackgroundQuestions.begin(), kBackgroundQuestions.end());
    if (shape.signedQuestions) {
        listing.questionsShown = "both";
        listing.instructionsShown = "both";
        for (const char* page : {"welcome", "part2"})
            listing.instructions.push_back({page, std::string("The ") + page + " page's instructions <in English> & more.",
                                            {"THANK-YOU HELP", "WATCH STORY"},
                                            clip(std::string("instructions-") + page, reviewFixtureSignedSeconds,
                                                 shape.withFrameFolders)});
    }

    // The design's Latin square, as planStudy fills it (stimuli/study/study.cpp).
    listing.groupVersion.assign(shape.stories, {});
    for (std::size_t s = 0; s < shape.stories; ++s)
        for (std::size_t g = 0; g < spec.versions; ++g) listing.groupVersion[s].push_back(phase1Version(spec, s, g));

    const std::size_t width = std::to_string(shape.participants).size();
    for (std::size_t p = 0; p < shape.participants; ++p) {
        const ParticipantSchedule schedule = participantSchedule(spec, p);
        ListedParticipant participant;
        std::string number = std::to_string(p + 1);
        participant.id = "P" + std::string(width > number.size() ? width - number.size() : 0, '0') + number;
        participant.group = schedule.group;
        for (std::size_t t = 0; t < schedule.phase1.size(); ++t)
            participant.phase1.push_back({t + 1, schedule.phase1[t].story, schedule.phase1[t].version});
        for (std::size_t t = 0; t < schedule.phase2.size(); ++t)
            participant.phase2.push_back({t + 1, schedule.phase2[t].sentence});
        listing.participants.push_back(participant);
    }
    return listing;
}

}  // namespace signstim::stimuli::testing
