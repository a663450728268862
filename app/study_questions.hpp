#pragma once
// Questions and instructions in ASL (issue 24 §1; stimuli/study/question_clips.hpp): checking
// that a study that signs them has the gloss to sign, and the timelines of their clips.
#include "app/study_units.hpp"

#include <vector>

namespace signstim::app {

// Before the study is planned: the instruction pages (the study file's, the others from
// SCENES/studies/instructions.json) with their gloss parsed when the study signs them, and every
// phase-1 question's gloss required when it signs the questions. Throws InputError (exit 2)
// naming the story file, line and field of a question without gloss.
void prepareSignedText(LoadedStudy& s);

// The timelines of a Questions or Instructions unit, one per clip, in the order of the listing's
// clips: a question's gloss signed by the story's signer in the story's space, its verb (if
// any) in the uninflected version — the clip is the same for every version, and a verb
// inflected toward the characters would show, in one version's form, the very agreement the
// question tests (docs/study.md).
std::vector<stimuli::Timeline> signedTextTimelines(const LoadedStudy& s, const stimuli::StudyUnit& unit);

}  // namespace signstim::app
