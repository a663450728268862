#pragma once
// What every writer of the study's exports (study_exports.cpp: CSV and JSON; study_sheets.cpp:
// printable pages) checks of a StudyListing before using it, and the small helpers they share.
// Internal to those files. A listing that contradicts itself is a bug in whoever composed it:
// each check throws std::invalid_argument saying what is wrong (stimuli/study/study_exports.hpp).
#include "stimuli/study/study_listing.hpp"

#include <cstddef>
#include <string>

namespace signstim::stimuli::exports_detail {

[[noreturn]] void inconsistent(const std::string& what);

inline std::string count(std::size_t value) { return std::to_string(value); }

// "A", "B", ...: how choices are named to participants, on the sheets and in the CSV.
inline std::string choiceLetter(std::size_t choice) { return std::string(1, static_cast<char>('A' + choice)); }

// The parts every writer reads: versions, stories with their clips and questions, sentences
// with their panels, and the group table when it is filled.
void checkStudy(const StudyListing& listing);

// The participant at `index`, with trials numbered 1, 2, ... in order and every index in
// range; when the group table is filled, their group exists and each phase-1 trial shows
// the version the table gives their group.
const ListedParticipant& checkedParticipant(const StudyListing& listing, std::size_t index);

}  // namespace signstim::stimuli::exports_detail
