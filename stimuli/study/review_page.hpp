#pragma once
// The review page of a rendered study: the static index.html at the root of its output folder,
// for the experimenter (it shows which version each clip is and every phase-2 panel mapping,
// which participants must never see). Written from a StudyListing alone.
//
// The page stands alone: inline CSS and a small inline script, no server, no network, nothing
// outside the output folder; it works when opened from file://. Every link, src and poster is
// the listing's relative path ('/' separators), percent-encoded where a character needs it.
//
// Size: a study of 24 participants x (12 + 8) trials has ~500 <video> elements but only one
// clip per story x version and per phase-2 sentence. Participant sections are collapsed
// <details> whose videos use preload="none" (nothing is fetched until a clip is played; the
// poster and the duration are shown as text), and their poster thumbnails load lazily when the
// section is opened. Only the story and sentence sections, one element per distinct clip, use
// preload="metadata".
//
// Every <video> carries data-expected-duration (seconds, 3 decimals) and data-frames (the
// frame count), which the browser check (tests/browser/check_review_page.py) compares with what
// the browser decodes. Same listing -> the same bytes.
#include "stimuli/study/study_exports.hpp"  // escapeHtml
#include "stimuli/study/study_listing.hpp"

#include <string>
#include <string_view>

namespace signstim::stimuli {

// The page's HTML (UTF-8). Throws std::invalid_argument when the listing refers to a story,
// version or sentence it does not hold (a bug of whoever filled it, not a user mistake).
std::string reviewPageHtml(const StudyListing& listing);

// A relative path as a URL path: bytes other than unreserved characters and '/' are
// percent-encoded ("clips/a b#1.mp4" -> "clips/a%20b%231.mp4"), so a file name can never be
// read as a query, a fragment or a scheme.
std::string encodeUrlPath(std::string_view path);

}  // namespace signstim::stimuli
