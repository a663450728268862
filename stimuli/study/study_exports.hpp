#pragma once
// The study's exports (SPEC §5): files for experiment software (a conditions CSV per
// participant for PsychoPy, OpenSesame and Gorilla; a jsPsych timeline_variables JSON per
// participant; an overview CSV of story x group -> version) and printable pages for the
// experimenter (the questions with their answer key; a phase-2 response sheet per participant).
// docs/exports.md describes every column and field and how each program loads them.
//
// Pure functions of a StudyListing (stimuli/study/study_listing.hpp): they return the file contents
// and write nothing; the study runner writes them atomically. Same listing -> the same bytes.
// Text is UTF-8 without a byte-order mark; numbers are locale-independent
// (common/number_format.hpp), durations in seconds to the millisecond.
//
// A listing that contradicts itself (an index out of range, trials not numbered 1, 2, ...,
// an answer that is not one of the choices, a non-finite duration, a sentence with a panel
// count other than the number of versions) is a bug in whoever composed it, not a user
// mistake: every writer throws std::invalid_argument saying what is wrong.
#include "stimuli/study/study_listing.hpp"

#include <cstddef>
#include <string>
#include <string_view>

namespace signstim::stimuli {

// One RFC 4180 field: the text as is, or in double quotes with inner quotes doubled when it
// holds a comma, a double quote, CR or LF.
std::string csvField(std::string_view text);

// Text safe both as HTML element content and inside a quoted attribute value:
// & < > " ' become entities, everything else (UTF-8 included) is kept.
std::string escapeHtml(std::string_view text);

// The conditions file of participant `participant` (index into listing.participants): a
// header row, then one row per trial, phase 1 then phase 2, in presentation order. Every row
// has every column (empty where it does not apply), as PsychoPy needs a rectangular table.
// Lines end in CRLF (RFC 4180); a field may hold an LF inside its quotes. Whole-number columns
// are never empty (qN_answer_index is -1 where a row has no question N), so that pandas, and
// with it PsychoPy's importConditions, reads them as integers; the participant's id is
// `participant_id`, apart from PsychoPy's own `participant` field. When the study signs its
// questions (any question has a clip), each question N adds qN_video_file and qN_video_name (the
// clip's path relative to the study folder, and its file name for a flat pool), empty where the
// row has no question N.
std::string conditionsCsv(const StudyListing& listing, std::size_t participant);

// The participant's Gorilla spreadsheet: the conditions file's columns and trials with the rows
// Gorilla's task flow needs around them -- `instructions` first, `break` before phase 2, `end`
// last, their wording in `text` -- and Gorilla's columns: ANSWER (question 1's correct choice as
// text, what a button response returns; qN_answer_text for the others), randomise_blocks and
// randomise_trials (left empty: the order is the schedule's). Text rows have trial 0. When the
// study signs its instructions, the instructions and break rows carry the welcome and part-2
// pages' clips in the clip columns and the pages' text (what the clips sign) in `text`.
std::string gorillaSpreadsheetCsv(const StudyListing& listing, std::size_t participant);

// jsPsych timeline variables of one participant: an object with "phase1" and "phase2"
// arrays, each element a trial in presentation order whose fields map onto
// jsPsychVideoButtonResponse ("video" is the array its `stimulus` wants) and
// jsPsychSurveyMultiChoice ("questions" is its `questions` parameter). 2-space indented,
// keys sorted.
std::string jspsychTimelineVariables(const StudyListing& listing, std::size_t participant);

// story x group -> version name, written from listing.groupVersion (which must have a row
// per story and the same number of groups in every row). Every participant's phase-1 trials
// are checked against it. Header: story,title,group_1,...,group_G (groups 1-based).
std::string overviewCsv(const StudyListing& listing);

// A printable, self-contained HTML page for the experimenter: every story with its title,
// its gloss sentences and its questions, the correct choice marked; one story per page.
std::string questionSheetHtml(const StudyListing& listing);

// A printable phase-2 response sheet for one participant: a block per trial in their order
// (trial number and sentence id) with a likertMinimum..likertMaximum row for each panel.
// It never shows which version is in which panel (no version names, no panel codes, no
// clip file names, which carry the code).
std::string likertResponseSheetHtml(const StudyListing& listing, std::size_t participant);

}  // namespace signstim::stimuli
