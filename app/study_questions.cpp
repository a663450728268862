#include "app/study_questions.hpp"

#include "common/error.hpp"
#include "stimuli/story/timeline_builder.hpp"

#include <filesystem>

namespace signstim::app {

using namespace signstim::stimuli;
namespace fs = std::filesystem;

void prepareSignedText(LoadedStudy& s) {
    StudyFile& study = s.study;
    if (showsSigned(study.questionsShown))
        for (std::size_t i = 0; i < s.stories.size(); ++i) {
            const Story& story = s.stories[i];
            for (std::size_t q = 0; q < story.questions.size(); ++q)
                if (story.questions[q].gloss.empty())
                    throw InputError(story.file, story.questions[q].line, "/questions/" + std::to_string(q) + "/gloss",
                                     "the study asks its questions in ASL (session.questions \"" + study.questionsShown +
                                         "\", the default \"both\"): give the question its \"gloss\", e.g. "
                                         "\"TOM ASK WHO\", or set \"session\": {\"questions\": \"english\"} in " +
                                         study.file + " (docs/study.md)");
        }
    // The pages the study file does not give come from SCENES/studies/instructions.json.
    const fs::path defaults = defaultInstructionsFile(s.world->scenes);
    study.instructions = withDefaultPages(study.instructions,
                                          fs::is_regular_file(defaults) ? loadInstructionsFile(defaults)
                                                                        : std::vector<StudyInstruction>{});
    s.instructionSentences.clear();
    if (!showsSigned(study.instructionsShown)) return;
    const StoryVocabulary vocabulary = s.world->vocabulary();
    for (const StudyInstruction& page : study.instructions) {
        std::vector<StorySentence> sentences;
        for (std::size_t i = 0; i < page.gloss.size(); ++i) {
            std::vector<std::string> spelled;
            const std::string field = page.field + "/gloss" + (page.gloss.size() > 1 ? "/" + std::to_string(i) : "");
            sentences.push_back(parseSignedGloss(page.gloss[i], nullptr, vocabulary, page.file, page.line, 0, field, &spelled));
            for (const std::string& word : spelled)
                s.signedTextNotes.push_back(page.file + ":" + std::to_string(page.line) + ": instructions " + page.page + ": " +
                                            word + " will be fingerspelled: no sign of the lexicon has the gloss " + word);
        }
        s.instructionSentences.push_back(std::move(sentences));
    }
}

namespace {

Timeline uninflectedTimeline(const LoadedStudy& s, const Story& story) {
    TimelineSources sources = s.world->sources(story);
    // One version only: the slot is the uninflected verb's own length, no animator file needed.
    sources.slotVersions = {VerbVersion::Uninflected};
    const TimelineOptions timing =
        timelineOptionsFor(s.settings.timing.given() ? s.settings.timing : story.timing, s.settings.rate);
    return buildTimeline(story, VerbVersion::Uninflected, sources, timing);
}

}  // namespace

std::vector<Timeline> signedTextTimelines(const LoadedStudy& s, const StudyUnit& unit) {
    std::vector<Timeline> timelines;
    if (unit.kind == StudyUnitKind::Questions) {
        const Story& story = s.stories.at(unit.index);
        const ListedStory& listed = s.listing.stories.at(unit.index);
        for (std::size_t q = 0; q < story.questions.size(); ++q) {
            if (listed.questions.at(q).clip.video.empty()) continue;
            Story question = story;  // its characters where the story placed them
            question.sentences = {story.questions[q].sentence};
            question.questions.clear();
            timelines.push_back(uninflectedTimeline(s, question));
        }
    } else if (unit.kind == StudyUnitKind::Instructions) {
        for (std::size_t p = 0; p < s.listing.instructions.size(); ++p) {
            if (s.listing.instructions[p].clip.video.empty()) continue;
            Story page;
            page.file = s.study.instructions.at(p).file;
            page.title = "instructions: " + s.listing.instructions[p].page;
            page.sentences = s.instructionSentences.at(p);
            timelines.push_back(uninflectedTimeline(s, page));
        }
    }
    return timelines;
}

}  // namespace signstim::app
