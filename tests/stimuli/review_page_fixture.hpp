#pragma once
// A hand-built StudyListing for the review page's tests, shaped like a real study (schedules
// from stimuli/study_design, SPEC §5 file names) but made without rendering: the unit tests
// read the page it gives, and the browser fixture (review_page_fixture_main.cpp) writes it
// to a folder with tiny real MP4s and posters for tests/browser/check_review_page.py.
#include "stimuli/study/study_listing.hpp"

#include <cstddef>

namespace signstim::stimuli::testing {

struct ReviewFixtureShape {
    std::size_t stories = 12;
    std::size_t participants = 24;
    std::size_t likertSentences = 8;
    bool withFrameFolders = false;  // fill ListedClip::frames
    // Issue 24: questions and instructions in ASL ("both"): every question with gloss and a
    // clip (story-NN_question-Q, lasting reviewFixtureSignedSeconds), instruction pages with clips.
    bool signedQuestions = false;
};
inline constexpr double reviewFixtureSignedSeconds = 1.4;

// Four versions (point, vector, animator, uninflected). Story clips of version v last
// reviewFixtureSeconds(v) at 15 fps; side-by-side clips last 2 s. Titles, glosses and questions
// carry characters that need escaping (& < > " ').
StudyListing reviewFixtureListing(const ReviewFixtureShape& shape = {});

// Duration of the story clips of version `version` in the fixture: 2.0, 1.8, 1.6, 1.4 s.
double reviewFixtureSeconds(std::size_t version);
inline constexpr double reviewFixtureFps = 15.0;
inline constexpr double reviewFixtureLikertSeconds = 2.0;

}  // namespace signstim::stimuli::testing
