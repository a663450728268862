#pragma once
// The study exports tests' shared pieces (study_exports_test.cpp, study_exports_documents_test.cpp):
// a strict RFC 4180 reader and a small synthetic listing built here by hand, not a rendered study.
#include "stimuli/study/study_exports.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace signstim::stimuli::exports_test {

using Records = std::vector<std::vector<std::string>>;
using Row = std::map<std::string, std::string>;

// ---- a strict RFC 4180 reader --------------------------------------------------------------

// Records end in CRLF (the last one too), fields are separated by commas, a quoted field may
// hold anything with its quotes doubled. Anything else (a bare LF, a quote inside an unquoted
// field, text after a closing quote) throws.
inline Records parseCsv(const std::string& text) {
    Records records;
    std::vector<std::string> record;
    std::string field;
    std::size_t i = 0;
    while (i < text.size()) {
        if (text[i] == '"') {
            ++i;
            for (;;) {
                if (i >= text.size()) throw std::runtime_error("unterminated quoted field");
                if (text[i] == '"') {
                    if (i + 1 < text.size() && text[i + 1] == '"') {
                        field += '"';
                        i += 2;
                        continue;
                    }
                    ++i;
                    break;
                }
                field += text[i++];
            }
        } else {
            while (i < text.size() && text[i] != ',' && text[i] != '\r' && text[i] != '\n') {
                if (text[i] == '"') throw std::runtime_error("quote inside an unquoted field");
                field += text[i++];
            }
        }
        record.push_back(std::move(field));
        field.clear();
        if (i < text.size() && text[i] == ',') {
            ++i;
            continue;
        }
        if (text.compare(i, 2, "\r\n") != 0) throw std::runtime_error("expected ',' or CRLF at byte " + std::to_string(i));
        i += 2;
        records.push_back(std::move(record));
        record.clear();
    }
    if (!record.empty()) throw std::runtime_error("the last record does not end in CRLF");
    return records;
}

// The data rows of a parsed table as column -> value (the table must be rectangular).
inline std::vector<Row> rowsOf(const Records& records) {
    std::vector<Row> rows;
    for (std::size_t r = 1; r < records.size(); ++r) {
        Row row;
        for (std::size_t c = 0; c < records[0].size(); ++c) row[records[0][c]] = records[r].at(c);
        rows.push_back(std::move(row));
    }
    return rows;
}

inline bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

inline std::size_t occurrences(const std::string& text, const std::string& part) {
    std::size_t found = 0;
    for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + part.size())) ++found;
    return found;
}

inline std::string lowercase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
    return text;
}

// ---- the fixture -----------------------------------------------------------------------------

inline const std::vector<std::string> allVersions = {"point", "vector", "animator", "uninflected", "mirrored"};
inline const std::vector<std::string> allLetters = {"P", "V", "A", "U", "M"};

// Titles that exercise quoting and escaping: a comma, quotes, a newline, non-ASCII, HTML.
inline const std::string awkwardTitle = "Zo\u00eb's \"big\" day, part 1\nand after";
inline const std::string htmlTitle = "Tom & <Jerry>";
inline const std::string htmlQuestion = "Is 2 < 3 & is \"yes\" right?";

inline std::string padded(std::size_t number) { return (number < 10 ? "0" : "") + std::to_string(number); }

// 4 stories (4 questions each; story 1's third question has 3 choices) in `versions` versions,
// one participant per group, 2 phase-2 sentences. Story orders and sentence orders differ
// between participants; group g sees story s in version (s + g) mod versions.
inline StudyListing fixture(std::size_t versions = 4) {
    StudyListing listing;
    listing.title = "Verb agreement comprehension";
    listing.studyFile = "scenes/studies/exports-test.json";
    listing.toolVersion = "0.4.0";
    listing.seed = 18446744073709551557ull;  // above 2^53: JSON must not carry it as a number
    listing.designHash = "9f86d081884c7d659a2feaa0c55ad015a3bf4f1b2b0b822cd15d6c15b0f00a08";
    listing.versions.assign(allVersions.begin(), allVersions.begin() + static_cast<std::ptrdiff_t>(versions));
    listing.versionLetters.assign(allLetters.begin(), allLetters.begin() + static_cast<std::ptrdiff_t>(versions));
    listing.size = "1280x720";
    listing.fps = "30";

    const std::vector<std::string> titles = {awkwardTitle, htmlTitle, "The copied homework", "\u00dcber den Fluss"};
    for (std::size_t s = 0; s < 4; ++s) {
        ListedStory story;
        story.id = "story-" + padded(s + 1);
        story.title = titles[s];
        story.file = "stories/" + story.id + ".json";
        story.sentences = {"JOHN IX(0.9) ASK MARY IX(-0.6)", "MARY IX(-0.6) GIVE-BOOK JOHN IX(0.9)"};
        for (std::size_t q = 0; q < 4; ++q) {
            ListedQuestion question;
            question.text = s == 1 && q == 0 ? htmlQuestion : "Who asked whom, in part " + std::to_string(q + 1) + "?";
            question.choices = {"John asked Mary", "Mary asked John", "Zo\u00eb asked \"nobody\"", "Nobody, really"};
            if (s == 0 && q == 2) question.choices.pop_back();
            question.answer = static_cast<int>((s + q) % question.choices.size());
            question.probeVerb = "ASK";
            question.probeSentence = static_cast<int>(q % 2);
            story.questions.push_back(question);
        }
        for (std::size_t v = 0; v < versions; ++v) {
            ListedClip clip;
            const std::string stem = story.id + "_version-" + listing.versions[v];
            clip.video = "clips/" + stem + ".mp4";
            clip.poster = "posters/" + stem + ".png";
            clip.durationSeconds = 10.0 + static_cast<double>(s) + 0.25 * static_cast<double>(v) + 0.0004;
            clip.frameCount = static_cast<std::uint64_t>(std::lround(clip.durationSeconds * 30));
            story.clips.push_back(clip);
        }
        listing.stories.push_back(story);
        std::vector<std::size_t> row;
        for (std::size_t g = 0; g < versions; ++g) row.push_back((s + g) % versions);
        listing.groupVersion.push_back(row);
    }

    for (std::size_t t = 0; t < 2; ++t) {
        ListedSentence sentence;
        sentence.id = "likert-" + padded(t + 1);
        sentence.gloss = t == 0 ? "JOHN IX(0.9) ASK MARY IX(-0.6)" : "ZOE IX(0.3) SEND BOB IX(-0.8)";
        sentence.verb = t == 0 ? "ASK" : "SEND";
        for (std::size_t k = 0; k < versions; ++k) {
            sentence.panelVersion.push_back((k + 1 + t) % versions);
            sentence.panelCode += listing.versionLetters[sentence.panelVersion.back()];
        }
        sentence.clip.video = "clips/" + sentence.id + "_panels-" + sentence.panelCode + ".mp4";
        sentence.clip.poster = "posters/" + sentence.id + "_panels-" + sentence.panelCode + ".png";
        sentence.clip.durationSeconds = 4.5;
        listing.sentences.push_back(sentence);
    }

    for (std::size_t p = 0; p < versions; ++p) {
        ListedParticipant participant;
        participant.id = "P" + padded(p + 1);
        participant.group = p;
        const std::vector<std::size_t> order = {(p + 3) % 4, (p + 1) % 4, p % 4, (p + 2) % 4};
        for (std::size_t i = 0; i < order.size(); ++i)
            participant.phase1.push_back({i + 1, order[i], listing.groupVersion[order[i]][participant.group]});
        participant.phase2.push_back({1, p % 2});
        participant.phase2.push_back({2, 1 - p % 2});
        listing.participants.push_back(participant);
    }
    return listing;
}

// The fixture as a study that signs its questions and instructions (issue 24): every question of
// every story but story 4's last has a clip named as the runner names it, and the welcome and
// part-2 pages have theirs. Synthetic paths; no clip exists.
inline StudyListing signedFixture(std::size_t versions = 4) {
    StudyListing listing = fixture(versions);
    listing.questionsShown = "both";
    listing.instructionsShown = "asl";
    for (ListedStory& story : listing.stories)
        for (std::size_t q = 0; q < story.questions.size(); ++q) {
            if (story.id == "story-04" && q + 1 == story.questions.size()) continue;
            const std::string stem = story.id + "_question-" + std::to_string(q + 1);
            story.questions[q].gloss = "WHO ASK WHO";
            story.questions[q].clip.video = "clips/" + stem + ".mp4";
            story.questions[q].clip.poster = "posters/" + stem + ".png";
            story.questions[q].clip.durationSeconds = 2.5;
        }
    for (const char* page : {"welcome", "part2"}) {
        ListedInstruction instruction;
        instruction.page = page;
        instruction.text = std::string("The ") + page + " page, in English.";
        instruction.gloss = {"THANK-YOU HELP"};
        instruction.clip.video = std::string("clips/instructions-") + page + ".mp4";
        instruction.clip.poster = std::string("posters/instructions-") + page + ".png";
        instruction.clip.durationSeconds = 6.25;
        listing.instructions.push_back(instruction);
    }
    return listing;
}

inline std::vector<Row> conditionRows(const StudyListing& listing, std::size_t participant) {
    return rowsOf(parseCsv(conditionsCsv(listing, participant)));
}

}  // namespace signstim::stimuli::exports_test
