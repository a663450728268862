#include "stimuli/study/study_listing_check.hpp"

#include "common/number_format.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace signstim::stimuli::exports_detail {
namespace {

void checkClip(const ListedClip& clip, const std::string& owner) {
    if (!std::isfinite(clip.durationSeconds) || clip.durationSeconds < 0.0)
        inconsistent(owner + ": clip '" + clip.video + "' has duration " + formatNumber(clip.durationSeconds) +
                     " s; expected a finite number of seconds, 0 or more");
}

}  // namespace

void inconsistent(const std::string& what) { throw std::invalid_argument("study listing: " + what); }

void checkStudy(const StudyListing& listing) {
    const std::size_t versions = listing.versions.size();
    // Panels and choices are lettered A..Z.
    if (versions == 0 || versions > 26) inconsistent(count(versions) + " versions; expected 1 to 26");
    for (const ListedStory& story : listing.stories) {
        // One clip per phase-1 version: every version, or the first ones when a version is in phase 2 only.
        if (story.clips.empty() || story.clips.size() > versions || story.clips.size() != listing.stories.front().clips.size())
            inconsistent(story.id + ": " + count(story.clips.size()) + " clips for " + count(versions) + " versions");
        for (const ListedClip& clip : story.clips) checkClip(clip, story.id);
        for (std::size_t q = 0; q < story.questions.size(); ++q) {
            const ListedQuestion& question = story.questions[q];
            const std::string name = story.id + " question " + count(q + 1);
            if (question.choices.empty() || question.choices.size() > 26)
                inconsistent(name + ": " + count(question.choices.size()) + " choices; expected 1 to 26");
            if (question.answer < 0 || static_cast<std::size_t>(question.answer) >= question.choices.size())
                inconsistent(name + ": answer " + std::to_string(question.answer) + " is not one of its " +
                             count(question.choices.size()) + " choices (0-based)");
        }
    }
    for (const ListedSentence& sentence : listing.sentences) {
        if (sentence.panelVersion.size() != likertPanelCount(listing) || sentence.panelVersion.size() > versions)
            inconsistent(sentence.id + ": " + count(sentence.panelVersion.size()) + " panels for " + count(versions) +
                         " versions");
        for (std::size_t version : sentence.panelVersion)
            if (version >= versions) inconsistent(sentence.id + ": panel shows version " + count(version));
        checkClip(sentence.clip, sentence.id);
    }
    if (!listing.groupVersion.empty()) {
        if (listing.groupVersion.size() != listing.stories.size())
            inconsistent("groupVersion has " + count(listing.groupVersion.size()) + " rows for " +
                         count(listing.stories.size()) + " stories");
        const std::size_t groups = listing.groupVersion.front().size();
        for (std::size_t s = 0; s < listing.groupVersion.size(); ++s) {
            const std::vector<std::size_t>& row = listing.groupVersion[s];
            if (row.empty() || row.size() != groups)
                inconsistent("groupVersion row " + count(s) + " has " + count(row.size()) + " groups; row 0 has " +
                             count(groups));
            for (std::size_t version : row)
                if (version >= listing.stories.at(s).clips.size()) inconsistent("groupVersion row " + count(s) + " names version " + count(version));
        }
    }
}

const ListedParticipant& checkedParticipant(const StudyListing& listing, std::size_t index) {
    if (index >= listing.participants.size())
        inconsistent("participant index " + count(index) + ", but there are " + count(listing.participants.size()) +
                     " participants");
    const ListedParticipant& participant = listing.participants[index];
    const bool haveGroups = !listing.groupVersion.empty();
    if (haveGroups && participant.group >= listing.groupVersion.front().size())
        inconsistent(participant.id + ": group " + count(participant.group) + " (0-based) does not exist");
    for (std::size_t i = 0; i < participant.phase1.size(); ++i) {
        const ListedPhase1Trial& trial = participant.phase1[i];
        const std::string name = participant.id + " phase-1 trial " + count(i + 1);
        if (trial.trial != i + 1) inconsistent(name + " is numbered " + count(trial.trial));
        if (trial.story >= listing.stories.size()) inconsistent(name + ": story index " + count(trial.story));
        if (trial.version >= listing.stories[trial.story].clips.size())
            inconsistent(name + ": version index " + count(trial.version));
        if (haveGroups && listing.groupVersion[trial.story][participant.group] != trial.version)
            inconsistent(name + ": " + listing.stories[trial.story].id + " in version " + count(trial.version) +
                         ", but groupVersion gives group " + count(participant.group) + " version " +
                         count(listing.groupVersion[trial.story][participant.group]));
    }
    for (std::size_t i = 0; i < participant.phase2.size(); ++i) {
        const ListedPhase2Trial& trial = participant.phase2[i];
        const std::string name = participant.id + " phase-2 trial " + count(i + 1);
        if (trial.trial != i + 1) inconsistent(name + " is numbered " + count(trial.trial));
        if (trial.sentence >= listing.sentences.size()) inconsistent(name + ": sentence index " + count(trial.sentence));
    }
    return participant;
}

}  // namespace signstim::stimuli::exports_detail
