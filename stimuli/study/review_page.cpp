#include "stimuli/study/review_page.hpp"

#include <algorithm>
#include <charconv>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace signstim::stimuli {

std::string encodeUrlPath(std::string_view path) {
    static constexpr char hex[] = "0123456789ABCDEF";
    std::string out;
    out.reserve(path.size());
    for (const char c : path) {
        const auto byte = static_cast<unsigned char>(c);
        const bool unreserved = (byte >= 'A' && byte <= 'Z') || (byte >= 'a' && byte <= 'z') ||
                                (byte >= '0' && byte <= '9') || byte == '-' || byte == '_' || byte == '.' ||
                                byte == '~' || byte == '/';
        if (unreserved) {
            out += c;
        } else {
            out += '%';
            out += hex[byte >> 4];
            out += hex[byte & 0x0F];
        }
    }
    return out;
}

// review_page.css and review_page.js, embedded at build time (stimuli/CMakeLists.txt).
namespace embedded {
extern const std::string_view reviewStyleSheet;
extern const std::string_view reviewScript;
}  // namespace embedded

namespace {

std::string seconds3(double seconds) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, seconds, std::chars_format::fixed, 3);
    if (result.ec != std::errc()) return "0.000";
    return std::string(buffer, result.ptr);
}

// Width and height from the listing's "1280x720", to reserve each picture's shape before it
// loads; {0, 0} when the text is not of that form.
std::pair<unsigned, unsigned> parseSize(std::string_view size) {
    const auto cross = size.find('x');
    if (cross == std::string_view::npos) return {0, 0};
    unsigned width = 0, height = 0;
    const std::string_view w = size.substr(0, cross), h = size.substr(cross + 1);
    const auto rw = std::from_chars(w.data(), w.data() + w.size(), width);
    const auto rh = std::from_chars(h.data(), h.data() + h.size(), height);
    if (rw.ec != std::errc() || rw.ptr != w.data() + w.size() || rh.ec != std::errc() ||
        rh.ptr != h.data() + h.size() || width == 0 || height == 0)
        return {0, 0};
    return {width, height};
}

// Element ids: readable ("story-03", "participant-P01", "P01-trial-1") and unique; characters
// outside [A-Za-z0-9_-] become '-', and a clash gets the element's position appended.
class Anchors {
public:
    std::string make(std::string_view readable, std::size_t position) {
        std::string id;
        for (const char c : readable) {
            const bool plain = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' ||
                               c == '_';
            id += plain ? c : '-';
        }
        if (id.empty()) id = "item";
        if (!used_.insert(id).second) {
            id += "-" + std::to_string(position + 1);
            while (!used_.insert(id).second) id += "-";
        }
        return id;
    }

private:
    std::set<std::string> used_;
};

class PageWriter {
public:
    explicit PageWriter(const StudyListing& listing) : listing_(listing), frame_(parseSize(listing.size)) {
        validate();
        for (std::size_t s = 0; s < listing.stories.size(); ++s)
            storyAnchor_.push_back(anchors_.make(listing.stories[s].id, s));
        for (std::size_t s = 0; s < listing.sentences.size(); ++s)
            sentenceAnchor_.push_back(anchors_.make(listing.sentences[s].id, s));
        for (std::size_t p = 0; p < listing.participants.size(); ++p)
            participantAnchor_.push_back(anchors_.make("participant-" + listing.participants[p].id, p));
    }

    std::string write() {
        out_ += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
        out_ += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
        out_ += "<meta name=\"generator\" content=\"signstim " + escapeHtml(listing_.toolVersion) + "\">\n";
        out_ += "<title>" + escapeHtml(listing_.title) + " \u2014 review</title>\n";
        out_ += "<style>";
        out_ += embedded::reviewStyleSheet;
        out_ += "</style>\n</head>\n<body>\n";
        header();
        counterbalancing();
        contents();
        out_ += "<main>\n";
        participants();
        stories();
        sentences();
        instructions();
        out_ += "</main>\n";
        out_ += "<footer>Written by signstim " + escapeHtml(listing_.toolVersion) + " from <code>" +
                escapeHtml(listing_.studyFile) +
                "</code>. A static page: it needs no server or network, and its links are relative to the "
                "study's output folder, so it works wherever the folder is moved.</footer>\n";
        out_ += "<script>";
        out_ += embedded::reviewScript;
        out_ += "</script>\n</body>\n</html>\n";
        return std::move(out_);
    }

private:
    void validate() const {
        const std::size_t versions = listing_.versions.size();
        if (listing_.versionLetters.size() != versions)
            throw std::invalid_argument("study listing: " + std::to_string(versions) + " versions but " +
                                        std::to_string(listing_.versionLetters.size()) + " version letters");
        for (const ListedStory& story : listing_.stories)
            if (story.clips.empty() || story.clips.size() > versions)  // fewer: a version in phase 2 only
                throw std::invalid_argument("study listing: " + story.id + " has " + std::to_string(story.clips.size()) +
                                            " clips for " + std::to_string(versions) + " versions");
        for (const ListedSentence& sentence : listing_.sentences)
            for (const std::size_t v : sentence.panelVersion)
                if (v >= versions)
                    throw std::invalid_argument("study listing: " + sentence.id + " shows version " + std::to_string(v) +
                                                " of " + std::to_string(versions));
        for (const ListedParticipant& participant : listing_.participants) {
            for (const ListedPhase1Trial& trial : participant.phase1)
                if (trial.story >= listing_.stories.size() || trial.version >= listing_.stories[trial.story].clips.size())
                    throw std::invalid_argument("study listing: " + participant.id + " phase-1 trial " +
                                                std::to_string(trial.trial) + " names story " +
                                                std::to_string(trial.story) + ", version " +
                                                std::to_string(trial.version) + " that the listing does not hold");
            for (const ListedPhase2Trial& trial : participant.phase2)
                if (trial.sentence >= listing_.sentences.size())
                    throw std::invalid_argument("study listing: " + participant.id + " phase-2 trial " +
                                                std::to_string(trial.trial) + " names sentence " +
                                                std::to_string(trial.sentence) + " that the listing does not hold");
        }
    }

    std::string versionName(std::size_t version) const { return listing_.versions[version]; }

    // "<span class="badge v1">V</span><span class="version-name">vector</span>"
    std::string versionBadge(std::size_t version, bool withName = true) const {
        std::string html = "<span class=\"badge v" + std::to_string(version % 5) + "\" title=\"" +
                           escapeHtml(listing_.versions[version]) + "\">" +
                           escapeHtml(listing_.versionLetters[version]) + "</span>";
        if (withName) html += "<span class=\"version-name\">" + escapeHtml(listing_.versions[version]) + "</span>";
        return html;
    }

    std::string sizeAttributes() const {
        if (frame_.first == 0) return {};
        return " width=\"" + std::to_string(frame_.first) + "\" height=\"" + std::to_string(frame_.second) + "\"";
    }

    // <video> with its poster, expected duration and frame count, and a caption of the duration
    // and the file links; `quad` for the 2x2 phase-2 clips (their own size, drawn larger).
    void video(const ListedClip& clip, std::string_view preload, std::string_view label, bool quad = false) {
        out_ += "<figure>";
        if (clip.video.empty()) {
            out_ += "<p class=\"muted\">no clip</p></figure>";
            return;
        }
        out_ += "<video controls playsinline preload=\"" + std::string(preload) + "\"";
        if (quad) out_ += " class=\"quad\"";
        else out_ += sizeAttributes();
        if (!clip.poster.empty()) out_ += " poster=\"" + escapeHtml(encodeUrlPath(clip.poster)) + "\"";
        out_ += " src=\"" + escapeHtml(encodeUrlPath(clip.video)) + "\"";
        out_ += " data-expected-duration=\"" + seconds3(clip.durationSeconds) + "\"";
        out_ += " data-frames=\"" + std::to_string(clip.frameCount) + "\"";
        out_ += " aria-label=\"" + escapeHtml(label) + "\"></video>\n<figcaption>";
        out_ += seconds3(clip.durationSeconds) + " s \u00b7 " + std::to_string(clip.frameCount) + " frames \u00b7 <a href=\"" +
                escapeHtml(encodeUrlPath(clip.video)) + "\">MP4</a>";
        if (!clip.poster.empty()) out_ += " \u00b7 <a href=\"" + escapeHtml(encodeUrlPath(clip.poster)) + "\">poster</a>";
        if (!clip.frames.empty()) out_ += " \u00b7 <a href=\"" + escapeHtml(encodeUrlPath(clip.frames)) + "/\">frames</a>";
        out_ += "</figcaption></figure>";
    }

    // `withClips`: each signed question's clip and gloss before its text and choices, as the
    // participant sees it (issue 24; the story sections, not the participants' trial tables).
    void questions(const ListedStory& story, bool withClips = false) {
        if (story.questions.empty()) {
            out_ += "<p class=\"muted\">no questions</p>";
            return;
        }
        out_ += "<ol class=\"questions\">\n";
        for (std::size_t q = 0; q < story.questions.size(); ++q) {
            const ListedQuestion& question = story.questions[q];
            out_ += "<li>";
            if (withClips && !question.clip.video.empty()) {
                out_ += "<div class=\"question-clip\">";
                video(question.clip, "metadata", story.id + " question " + std::to_string(q + 1) + " in ASL");
                out_ += "<p class=\"muted\">asked in ASL: <span class=\"gloss\">" + escapeHtml(question.gloss) + "</span></p></div>";
            }
            out_ += "<p>" + escapeHtml(question.text) + "</p><ol class=\"choices\" type=\"A\">";
            for (std::size_t c = 0; c < question.choices.size(); ++c) {
                const bool answer = static_cast<int>(c) == question.answer;
                out_ += answer ? "<li class=\"answer\">" : "<li>";
                out_ += escapeHtml(question.choices[c]);
                if (answer) out_ += "<span class=\"key\">\u2713 answer</span>";
                out_ += "</li>";
            }
            out_ += "</ol>";
            if (!question.probeVerb.empty())
                out_ += "<p class=\"probe\">asks about <span class=\"gloss\">" + escapeHtml(question.probeVerb) +
                        "</span> in sentence " + std::to_string(question.probeSentence + 1) + "</p>";
            out_ += "</li>\n";
        }
        out_ += "</ol>";
    }

    // "A = vector" for each panel, as a small table.
    void mapping(const ListedSentence& sentence) {
        out_ += "<table class=\"mapping\"><thead><tr><th>Panel</th><th>Version</th></tr></thead><tbody>";
        static constexpr std::string_view corners[] = {"top left", "top right", "bottom left", "bottom right"};
        for (std::size_t k = 0; k < sentence.panelVersion.size(); ++k) {
            const std::string label = k < 26 ? std::string(1, static_cast<char>('A' + k)) : std::to_string(k + 1);
            out_ += "<tr><td><strong>" + label + "</strong>";
            if (sentence.panelVersion.size() == 4) out_ += " <span class=\"muted\">" + std::string(corners[k]) + "</span>";
            out_ += "</td><td>" + versionBadge(sentence.panelVersion[k]) + "</td></tr>";
        }
        out_ += "</tbody></table>";
    }

    void header() {
        const StudyListing& l = listing_;
        std::size_t videos = 0;
        for (const ListedStory& story : l.stories) videos += story.clips.size();
        videos += l.sentences.size();
        out_ += "<header>\n<h1>" + escapeHtml(l.title) + "</h1>\n";
        out_ += "<p class=\"lede\">Review page of the rendered study, for the experimenter: each participant's trials "
                "in order, each story in its versions side by side, and each phase-2 sentence with its panel "
                "mapping. It names the version of every clip, which participants must not see.</p>\n";
        out_ += "<dl class=\"facts\">\n";
        out_ += "<dt>Study file</dt><dd><code>" + escapeHtml(l.studyFile) + "</code></dd>\n";
        out_ += "<dt>Tool</dt><dd>signstim " + escapeHtml(l.toolVersion) + "</dd>\n";
        out_ += "<dt>Seed</dt><dd><code>" + std::to_string(l.seed) + "</code></dd>\n";
        out_ += "<dt>Design hash</dt><dd><code>" + escapeHtml(l.designHash) + "</code></dd>\n";
        out_ += "<dt>Render settings</dt><dd>" + escapeHtml(l.size) + ", " + escapeHtml(l.fps) + " fps, MSAA " +
                std::to_string(l.msaa) + "\u00d7</dd>\n";
        out_ += "<dt>Versions</dt><dd>";
        for (std::size_t v = 0; v < l.versions.size(); ++v) {
            if (v > 0) out_ += " &nbsp; ";
            out_ += versionBadge(v);
        }
        out_ += "</dd>\n";
        out_ += "<dt>Design</dt><dd>" + std::to_string(l.participants.size()) + " participants; phase 1: " +
                std::to_string(l.stories.size()) + " stories \u00d7 " + std::to_string(l.versions.size()) +
                " versions; phase 2: " + std::to_string(l.sentences.size()) + " side-by-side sentences rated " +
                std::to_string(l.likertMinimum) + " to " + std::to_string(l.likertMaximum) + "; " +
                std::to_string(videos) + " clips</dd>\n";
        // Issue 22 hook: draft animator files the clips use (--allow-draft-animator).
        if (!l.draftAnimator.empty()) {
            out_ += "<dt>Draft animator files</dt><dd><strong>" + std::to_string(l.draftAnimator.size()) +
                    " animator file(s) are drafts from the point model, not an animator's work:</strong>";
            for (const std::string& f : l.draftAnimator) out_ += " <code>" + escapeHtml(f) + "</code>";
            out_ += "</dd>\n";
        }
        out_ += "</dl>\n</header>\n";
    }

    // The counterbalancing at a glance: the design's Latin square (story x group -> version, the
    // content of overview.csv, linked), how many participants each group has, and how often each
    // version sits at each phase-1 trial position across the participants (a random order leaves
    // these uneven; order "balanced" evens them over every complete block, study_design.hpp).
    void counterbalancing() {
        const StudyListing& l = listing_;
        const std::size_t versions = l.versions.size();
        out_ += "<section id=\"counterbalancing\" class=\"counterbalancing\">\n<h2>Counterbalancing</h2>\n";
        out_ += "<div class=\"grid\">\n<div>\n<h3>Version of each story in each group</h3>\n";
        if (l.groupVersion.empty() || l.groupVersion.front().empty()) {
            out_ += "<p class=\"muted\">no group table in this listing</p>\n";
        } else {
            const std::size_t groups = l.groupVersion.front().size();
            std::vector<std::size_t> members(groups, 0);
            for (const ListedParticipant& p : l.participants)
                if (p.group < groups) ++members[p.group];
            out_ += "<table class=\"square\"><thead><tr><th class=\"story\">Story</th>";
            for (std::size_t g = 0; g < groups; ++g)
                out_ += "<th>Group " + std::to_string(g + 1) + "<br><span class=\"muted\">" +
                        std::to_string(members[g]) + (members[g] == 1 ? " participant" : " participants") +
                        "</span></th>";
            out_ += "</tr></thead><tbody>\n";
            for (std::size_t s = 0; s < l.groupVersion.size() && s < l.stories.size(); ++s) {
                out_ += "<tr><td class=\"story\"><a href=\"#" + storyAnchor_[s] + "\">" + escapeHtml(l.stories[s].id) +
                        "</a></td>";
                for (std::size_t g = 0; g < groups; ++g) {
                    const std::size_t v = l.groupVersion[s][g];
                    out_ += "<td>" + (v < versions ? versionBadge(v, false) : std::string("?")) + "</td>";
                }
                out_ += "</tr>\n";
            }
            out_ += "</tbody></table>\n";
        }
        out_ += "<p class=\"note\">The same table as a file: <a href=\"overview.csv\">overview.csv</a> "
                "(story &times; group &rarr; version).</p>\n</div>\n";
        positionCounts();
        out_ += "</div>\n</section>\n";
    }

    void positionCounts() {
        const StudyListing& l = listing_;
        const std::size_t versions = l.versions.size();
        std::size_t positions = 0;
        for (const ListedParticipant& p : l.participants) positions = std::max(positions, p.phase1.size());
        out_ += "<div>\n<h3>Versions by phase-1 trial position</h3>\n";
        if (positions == 0 || versions == 0) {
            out_ += "<p class=\"muted\">no phase-1 trials</p>\n</div>\n";
            return;
        }
        // count[v][i]: participants whose trial i + 1 shows version v.
        std::vector<std::vector<std::size_t>> count(versions, std::vector<std::size_t>(positions, 0));
        for (const ListedParticipant& p : l.participants)
            for (std::size_t i = 0; i < p.phase1.size(); ++i) ++count[p.phase1[i].version][i];
        // Even: participants / versions at every position (when it divides).
        const bool divides = l.participants.size() % versions == 0;
        const std::size_t even = l.participants.size() / versions;
        std::size_t low = l.participants.size(), high = 0;
        out_ += "<table class=\"positions\"><thead><tr><th>Version</th>";
        for (std::size_t i = 0; i < positions; ++i) out_ += "<th>" + std::to_string(i + 1) + "</th>";
        out_ += "</tr></thead><tbody>\n";
        for (std::size_t v = 0; v < versions; ++v) {
            out_ += "<tr><th>" + versionBadge(v) + "</th>";
            for (std::size_t i = 0; i < positions; ++i) {
                const std::size_t n = count[v][i];
                low = std::min(low, n);
                high = std::max(high, n);
                out_ += std::string(divides ? (n == even ? "<td class=\"even\">" : "<td class=\"off\">") : "<td>") +
                        std::to_string(n) + "</td>";
            }
            out_ += "</tr>\n";
        }
        out_ += "</tbody></table>\n<p class=\"note\">Participants whose trial at that position shows that version";
        if (divides)
            out_ += "; " + std::to_string(even) + " everywhere when balanced. Here: " +
                    (low == high ? std::to_string(low) + " everywhere (balanced)"
                                 : std::to_string(low) + " to " + std::to_string(high) + " (cells off " +
                                       std::to_string(even) + " marked)");
        out_ += ". The study file's <code>\"order\": \"balanced\"</code> evens them over every complete block of "
                "participants (docs/study.md).</p>\n</div>\n";
    }

    void contents() {
        out_ += "<nav class=\"toc\" aria-label=\"Contents\">\n<h2>Contents</h2>\n<ol>\n";
        out_ += "<li><a href=\"#counterbalancing\">Counterbalancing</a> <span class=\"muted\">(story &times; group, "
                "versions by trial position, <a href=\"overview.csv\">overview.csv</a>)</span></li>\n";
        out_ += "<li><a href=\"#participants\">Participants</a> <span class=\"muted\">(" +
                std::to_string(listing_.participants.size()) + ")</span><ul class=\"links\">";
        for (std::size_t p = 0; p < listing_.participants.size(); ++p)
            out_ += "<li><a href=\"#" + participantAnchor_[p] + "\">" + escapeHtml(listing_.participants[p].id) +
                    "</a></li>";
        out_ += "</ul></li>\n";
        out_ += "<li><a href=\"#stories\">Stories</a> <span class=\"muted\">(" + std::to_string(listing_.stories.size()) +
                ")</span><ul class=\"links wide\">";
        for (std::size_t s = 0; s < listing_.stories.size(); ++s)
            out_ += "<li><a href=\"#" + storyAnchor_[s] + "\">" + escapeHtml(listing_.stories[s].id) + "</a> " +
                    escapeHtml(listing_.stories[s].title) + "</li>";
        out_ += "</ul></li>\n";
        out_ += "<li><a href=\"#sentences\">Phase 2 sentences</a> <span class=\"muted\">(" +
                std::to_string(listing_.sentences.size()) + ")</span><ul class=\"links wide\">";
        for (std::size_t s = 0; s < listing_.sentences.size(); ++s)
            out_ += "<li><a href=\"#" + sentenceAnchor_[s] + "\">" + escapeHtml(listing_.sentences[s].id) +
                    "</a> <span class=\"gloss\">" + escapeHtml(listing_.sentences[s].gloss) + "</span></li>";
        out_ += "</ul></li>\n</ol>\n</nav>\n";
    }

    void participants() {
        out_ += "<section id=\"participants\">\n<h2>Participants</h2>\n";
        out_ += "<p class=\"note\">Each participant's set in presentation order. Open a participant to see their "
                "trials; a clip loads when it is played.</p>\n";
        out_ += "<div class=\"toolbar\"><button type=\"button\" data-participants=\"open\">Open all</button>"
                "<button type=\"button\" data-participants=\"close\">Close all</button></div>\n";
        for (std::size_t p = 0; p < listing_.participants.size(); ++p) participant(p);
        out_ += "</section>\n";
    }

    void participant(std::size_t index) {
        const ListedParticipant& participant = listing_.participants[index];
        const std::string& anchor = participantAnchor_[index];
        out_ += "<details class=\"participant\" id=\"" + anchor + "\">\n<summary><span class=\"pid\">" +
                escapeHtml(participant.id) + "</span><span class=\"muted\">group " +
                std::to_string(participant.group + 1) + " \u00b7 " + std::to_string(participant.phase1.size()) +
                " phase-1 trials \u00b7 " + std::to_string(participant.phase2.size()) +
                " phase-2 trials</span></summary>\n<div class=\"body\">\n";

        out_ += "<h3>Phase 1 \u2014 comprehension</h3>\n";
        if (participant.phase1.empty()) {
            out_ += "<p class=\"muted\">no phase-1 trials</p>\n";
        } else {
            // The order at a glance: a poster per trial, linked to its row.
            out_ += "<ol class=\"strip\" aria-label=\"Phase 1 order\">";
            for (const ListedPhase1Trial& trial : participant.phase1) {
                const ListedStory& story = listing_.stories[trial.story];
                const ListedClip& clip = story.clips[trial.version];
                out_ += "<li><a href=\"#" + anchor + "-trial-" + std::to_string(trial.trial) + "\">";
                if (!clip.poster.empty())
                    out_ += "<img loading=\"lazy\" src=\"" + escapeHtml(encodeUrlPath(clip.poster)) + "\"" +
                            sizeAttributes() + " alt=\"" + escapeHtml(story.id + ", " + versionName(trial.version)) +
                            "\">";
                out_ += std::to_string(trial.trial) + ". " + escapeHtml(story.id) + "</a> " +
                        versionBadge(trial.version, false) + "</li>";
            }
            out_ += "</ol>\n";
            out_ += "<table class=\"trials\">\n<thead><tr><th>#</th><th>Story, version</th><th>Clip</th>"
                    "<th>Questions (answer key marked)</th></tr></thead>\n<tbody>\n";
            for (const ListedPhase1Trial& trial : participant.phase1) {
                const ListedStory& story = listing_.stories[trial.story];
                out_ += "<tr id=\"" + anchor + "-trial-" + std::to_string(trial.trial) + "\"><td class=\"num\">" +
                        std::to_string(trial.trial) + "</td><td class=\"story\"><a href=\"#" + storyAnchor_[trial.story] + "\">" +
                        escapeHtml(story.id) + "</a><br>" + escapeHtml(story.title) + "<div class=\"version\">" +
                        versionBadge(trial.version) + "</div></td><td class=\"clip\">";
                video(story.clips[trial.version], "none",
                      participant.id + " trial " + std::to_string(trial.trial) + ": " + story.id + ", " +
                          versionName(trial.version));
                out_ += "</td><td>";
                questions(story);
                out_ += "</td></tr>\n";
            }
            out_ += "</tbody>\n</table>\n";
        }

        out_ += "<h3>Phase 2 \u2014 side by side, rated " + std::to_string(listing_.likertMinimum) + " to " +
                std::to_string(listing_.likertMaximum) + "</h3>\n";
        if (participant.phase2.empty()) {
            out_ += "<p class=\"muted\">no phase-2 trials</p>\n";
        } else {
            out_ += "<table class=\"trials\">\n<thead><tr><th>#</th><th>Sentence</th><th>Clip</th>"
                    "<th>Panels</th></tr></thead>\n<tbody>\n";
            for (const ListedPhase2Trial& trial : participant.phase2) {
                const ListedSentence& sentence = listing_.sentences[trial.sentence];
                out_ += "<tr id=\"" + anchor + "-likert-" + std::to_string(trial.trial) + "\"><td class=\"num\">" +
                        std::to_string(trial.trial) + "</td><td><a href=\"#" + sentenceAnchor_[trial.sentence] + "\">" +
                        escapeHtml(sentence.id) + "</a><br><span class=\"gloss\">" + escapeHtml(sentence.gloss) +
                        "</span></td><td class=\"clip quad\">";
                video(sentence.clip, "none",
                      participant.id + " phase-2 trial " + std::to_string(trial.trial) + ": " + sentence.id, true);
                out_ += "</td><td>";
                mapping(sentence);
                out_ += "</td></tr>\n";
            }
            out_ += "</tbody>\n</table>\n";
        }
        out_ += "</div>\n</details>\n";
    }

    void stories() {
        out_ += "<section id=\"stories\">\n<h2>Stories</h2>\n";
        out_ += "<p class=\"note\">Each story in every version, side by side, with its sentences and questions.</p>\n";
        for (std::size_t s = 0; s < listing_.stories.size(); ++s) {
            const ListedStory& story = listing_.stories[s];
            out_ += "<section class=\"story\" id=\"" + storyAnchor_[s] + "\">\n<h3>" + escapeHtml(story.id) +
                    " \u2014 " + escapeHtml(story.title) + "</h3>\n";
            if (!story.file.empty()) out_ += "<p class=\"muted\">from <code>" + escapeHtml(story.file) + "</code></p>\n";
            out_ += "<div class=\"versions\">\n";
            for (std::size_t v = 0; v < story.clips.size(); ++v) {
                out_ += "<div class=\"version\">";
                video(story.clips[v], "metadata", story.id + ", " + versionName(v));
                out_ += "<p>" + versionBadge(v) + "</p></div>\n";
            }
            out_ += "</div>\n<h4>Sentences</h4>\n<ol class=\"sentences\">";
            for (const std::string& gloss : story.sentences)
                out_ += "<li><span class=\"gloss\">" + escapeHtml(gloss) + "</span></li>";
            out_ += "</ol>\n<h4>Questions</h4>\n";
            questions(story, true);
            out_ += "\n</section>\n";
        }
        out_ += "</section>\n";
    }

    void sentences() {
        out_ += "<section id=\"sentences\">\n<h2>Phase 2 sentences</h2>\n";
        out_ += "<p class=\"note\">Each side-by-side clip with the version in each panel. Participants see only the "
                "panel letters.</p>\n";
        for (std::size_t s = 0; s < listing_.sentences.size(); ++s) {
            const ListedSentence& sentence = listing_.sentences[s];
            out_ += "<section class=\"sentence\" id=\"" + sentenceAnchor_[s] + "\">\n<h3>" + escapeHtml(sentence.id) +
                    " \u2014 <span class=\"gloss\">" + escapeHtml(sentence.gloss) + "</span></h3>\n";
            out_ += "<p class=\"muted\">verb <span class=\"gloss\">" + escapeHtml(sentence.verb) +
                    "</span> \u00b7 panels <code>" + escapeHtml(sentence.panelCode) + "</code></p>\n";
            out_ += "<div class=\"sentence-body\">";
            video(sentence.clip, "metadata", sentence.id, true);
            mapping(sentence);
            out_ += "</div>\n</section>\n";
        }
        out_ += "</section>\n";
    }

    // Issue 24: the experiment's instruction pages, their clips and text.
    void instructions() {
        if (listing_.instructions.empty()) return;
        out_ += "<section id=\"instructions\">\n<h2>Instructions</h2>\n";
        out_ += "<p class=\"note\">What the experiment's instruction pages show (" + escapeHtml(listing_.instructionsShown) +
                "); questions are asked in " + escapeHtml(listing_.questionsShown) + ".</p>\n";
        for (const ListedInstruction& page : listing_.instructions) {
            out_ += "<section class=\"instruction\">\n<h3>" + escapeHtml(page.page) + "</h3>\n";
            if (!page.clip.video.empty()) video(page.clip, "metadata", "instructions " + page.page + " in ASL");
            out_ += "<p>" + escapeHtml(page.text) + "</p>\n<ol class=\"sentences\">";
            for (const std::string& gloss : page.gloss) out_ += "<li><span class=\"gloss\">" + escapeHtml(gloss) + "</span></li>";
            out_ += "</ol>\n</section>\n";
        }
        out_ += "</section>\n";
    }

    const StudyListing& listing_;
    std::pair<unsigned, unsigned> frame_;
    Anchors anchors_;
    std::vector<std::string> storyAnchor_, sentenceAnchor_, participantAnchor_;
    std::string out_;
};

}  // namespace

std::string reviewPageHtml(const StudyListing& listing) {
    return PageWriter(listing).write();
}

}  // namespace signstim::stimuli
