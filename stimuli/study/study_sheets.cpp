// The printable pages for the experimenter (SPEC §5, docs/exports.md): the questions with their
// answer key, and a phase-2 response sheet per participant. Declared in study_exports.hpp.
#include "stimuli/study/study_design.hpp"
#include "stimuli/study/study_exports.hpp"
#include "stimuli/study/study_listing_check.hpp"

#include <algorithm>
#include <string_view>

namespace signstim::stimuli {
namespace {

using exports_detail::checkedParticipant;
using exports_detail::checkStudy;
using exports_detail::choiceLetter;
using exports_detail::count;
using exports_detail::inconsistent;

// ---- HTML ---------------------------------------------------------------------------------

// Shared by both sheets: plain type that prints well in black and white, no fixed page size
// (A4 and Letter both fit), and nothing loaded from elsewhere.
constexpr std::string_view baseCss =
    "body { font-family: Georgia, 'Times New Roman', serif; font-size: 11pt; line-height: 1.35; color: #000;"
    " background: #fff; max-width: 46em; margin: 2em auto; padding: 0 1em; }\n"
    "h1 { font-size: 16pt; margin: 0 0 0.2em; }\n"
    "h2 { font-size: 13pt; margin: 0 0 0.4em; }\n"
    "h3 { font-size: 11pt; margin: 0.8em 0 0.3em; }\n"
    "header { border-bottom: 1px solid #000; margin-bottom: 1.2em; padding-bottom: 0.4em; }\n"
    ".meta { font-size: 9pt; color: #333; }\n"
    "@media print {\n"
    "  @page { margin: 15mm; }\n"
    "  body { max-width: none; margin: 0; padding: 0; font-size: 10.5pt; }\n"
    "}\n";

std::string htmlPage(const std::string& title, std::string_view css, const std::string& body) {
    std::string page = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
    page += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
    page += "<title>" + escapeHtml(title) + "</title>\n<style>\n";
    page += baseCss;
    page += css;
    page += "</style>\n</head>\n<body>\n";
    page += body;
    page += "</body>\n</html>\n";
    return page;
}

constexpr std::string_view questionSheetCss =
    ".story + .story { margin-top: 2.5em; }\n"
    ".source { font-size: 9pt; color: #333; margin: 0 0 0.6em; }\n"
    "ol.gloss { font-family: 'Courier New', Courier, monospace; font-size: 10pt; }\n"
    "ol.questions > li { margin-bottom: 0.8em; }\n"
    ".prompt { margin: 0; }\n"
    ".probe { font-size: 9pt; color: #333; margin: 0; }\n"
    "ul.choices { list-style: none; margin: 0.2em 0 0; padding-left: 1.2em; }\n"
    ".letter { display: inline-block; min-width: 1.6em; font-weight: bold; }\n"
    ".answer { font-weight: bold; }\n"
    ".answer .mark { border: 1px solid #000; padding: 0 0.3em; margin-left: 0.5em; font-size: 9pt; }\n"
    ".key { border-top: 1px solid #999; padding-top: 0.3em; }\n"
    "@media print {\n"
    "  .story { break-after: page; page-break-after: always; }\n"
    "  .story:last-of-type { break-after: auto; page-break-after: auto; }\n"
    "  .story + .story { margin-top: 0; }\n"
    "  ol.questions > li { break-inside: avoid; page-break-inside: avoid; }\n"
    "}\n";

std::string questionBlock(const ListedQuestion& question) {
    std::string html = "<li>\n<p class=\"prompt\">" + escapeHtml(question.text) + "</p>\n";
    if (!question.probeVerb.empty())
        html += "<p class=\"probe\">About " + escapeHtml(question.probeVerb) + " in sentence " +
                count(static_cast<std::size_t>(std::max(question.probeSentence, 0)) + 1) + "</p>\n";
    html += "<ul class=\"choices\">\n";
    for (std::size_t c = 0; c < question.choices.size(); ++c) {
        const bool isAnswer = c == static_cast<std::size_t>(question.answer);
        html += isAnswer ? "<li class=\"answer\">" : "<li>";
        html += "<span class=\"letter\">" + choiceLetter(c) + "</span> " + escapeHtml(question.choices[c]);
        // Marked in words as well as in bold, so a photocopy still shows it.
        if (isAnswer) html += " <span class=\"mark\">&#10004; answer</span>";
        html += "</li>\n";
    }
    html += "</ul>\n</li>\n";
    return html;
}

std::string storySection(const ListedStory& story) {
    std::string html = "<section class=\"story\" id=\"" + escapeHtml(story.id) + "\">\n";
    html += "<h2>" + escapeHtml(story.id) + ": " + escapeHtml(story.title) + "</h2>\n";
    if (!story.file.empty()) html += "<p class=\"source\">" + escapeHtml(story.file) + "</p>\n";
    html += "<h3>Sentences</h3>\n<ol class=\"gloss\">\n";
    for (const std::string& sentence : story.sentences) html += "<li>" + escapeHtml(sentence) + "</li>\n";
    html += "</ol>\n<h3>Questions</h3>\n<ol class=\"questions\">\n";
    for (const ListedQuestion& question : story.questions) html += questionBlock(question);
    html += "</ol>\n";
    if (!story.questions.empty()) {
        html += "<p class=\"key\">Answer key:";
        for (std::size_t q = 0; q < story.questions.size(); ++q)
            html += (q == 0 ? " " : " &middot; ") + count(q + 1) + "&nbsp;" +
                    choiceLetter(static_cast<std::size_t>(story.questions[q].answer));
        html += "</p>\n";
    }
    html += "</section>\n";
    return html;
}

constexpr std::string_view responseSheetCss =
    ".fill { display: inline-block; min-width: 9em; border-bottom: 1px solid #000; }\n"
    ".trial { margin: 0 0 1.2em; }\n"
    ".trial h2 { font-size: 12pt; }\n"
    ".sentence { font-weight: normal; font-size: 10pt; margin-left: 0.8em; }\n"
    "table.scale { border-collapse: separate; border-spacing: 1.2mm 1mm; }\n"
    "table.scale th { text-align: left; font-weight: bold; padding-right: 3mm; white-space: nowrap; }\n"
    ".box { display: inline-block; width: 8mm; height: 8mm; line-height: 8mm; border: 1px solid #000;"
    " border-radius: 50%; text-align: center; font-size: 9pt; }\n"
    "@media print {\n"
    "  .trial { break-inside: avoid; page-break-inside: avoid; }\n"
    "}\n";

std::string ratingTable(const StudyListing& listing) {
    std::string html = "<table class=\"scale\">\n";
    for (std::size_t panel = 0; panel < likertPanelCount(listing); ++panel) {
        html += "<tr><th scope=\"row\">Panel " + panelLabel(panel) + "</th>";
        for (int rating = listing.likertMinimum; rating <= listing.likertMaximum; ++rating)
            html += "<td><span class=\"box\">" + std::to_string(rating) + "</span></td>";
        html += "</tr>\n";
    }
    html += "</table>\n";
    return html;
}

}  // namespace

std::string questionSheetHtml(const StudyListing& listing) {
    checkStudy(listing);
    std::string body = "<header>\n<h1>" + escapeHtml(listing.title) + "</h1>\n";
    body += "<p>Comprehension questions and answer key &middot; for the experimenter</p>\n";
    body += "<p class=\"meta\">" + count(listing.stories.size()) + " stories &middot; design " +
            escapeHtml(listing.designHash) + " &middot; seed " + std::to_string(listing.seed) + " &middot; signstim " +
            escapeHtml(listing.toolVersion) + "</p>\n</header>\n";
    for (const ListedStory& story : listing.stories) body += storySection(story);
    return htmlPage(listing.title + " - questions and answer key", questionSheetCss, body);
}

std::string likertResponseSheetHtml(const StudyListing& listing, std::size_t participantIndex) {
    checkStudy(listing);
    const ListedParticipant& participant = checkedParticipant(listing, participantIndex);
    if (listing.likertMinimum > listing.likertMaximum || listing.likertMaximum - listing.likertMinimum > 100)
        inconsistent("rating scale " + std::to_string(listing.likertMinimum) + " to " +
                     std::to_string(listing.likertMaximum));

    std::string body = "<header>\n<h1>" + escapeHtml(listing.title) + "</h1>\n";
    body += "<p>Ratings &middot; participant <strong>" + escapeHtml(participant.id) +
            "</strong> &middot; date <span class=\"fill\"></span></p>\n";
    body += "<p>After each video, circle one number for every panel: " + std::to_string(listing.likertMinimum) +
            " = lowest, " + std::to_string(listing.likertMaximum) + " = highest.</p>\n</header>\n";
    // Deliberately nothing per trial but its number and sentence id: the panel code and the
    // clip's file name ("likert-05_panels-VPAU.mp4") would tell which version is where.
    for (const ListedPhase2Trial& trial : participant.phase2) {
        body += "<section class=\"trial\">\n<h2>Trial " + count(trial.trial) + "<span class=\"sentence\">" +
                escapeHtml(listing.sentences[trial.sentence].id) + "</span></h2>\n";
        body += ratingTable(listing);
        body += "</section>\n";
    }
    return htmlPage(listing.title + " - ratings - " + participant.id, responseSheetCss, body);
}

}  // namespace signstim::stimuli
