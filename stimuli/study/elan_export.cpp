#include "stimuli/study/elan_export.hpp"

#include "stimuli/study/study_exports.hpp"  // escapeHtml

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>

namespace signstim::stimuli {

namespace {

bool isCapital(char c) { return c >= 'A' && c <= 'Z'; }

// Keys a letter takes in the builder's fingerspellingSegment (stimuli/story/timeline.cpp): J
// draws its hook with three keys of the I hand, Z traces four corners with the 1 hand, every
// other letter is held between two keys of its own shape.
std::size_t keysOfLetter(char letter) { return letter == 'J' ? 3 : letter == 'Z' ? 4 : 2; }
std::string shapeOfLetter(char letter) { return letter == 'J' ? "I" : letter == 'Z' ? "1" : std::string(1, letter); }

struct Annotation {
    std::string tier;
    std::int64_t startMs = 0, endMs = 0;
    std::string value;
};

// Times on the clip's frame grid (docs/study.md, "ELAN files").
class FrameGrid {
public:
    explicit FrameGrid(double fps) : fps_(fps > 0.0 ? fps : 30.0) {}
    std::int64_t frameOf(double seconds) const { return std::max<std::int64_t>(0, std::llround(seconds * fps_)); }
    std::int64_t ms(std::int64_t frame) const { return std::llround(static_cast<double>(frame) * 1000.0 / fps_); }

private:
    double fps_;
};

// Annotations of one tier, kept in time order without overlap: each lasts at least a frame and
// starts no earlier than the previous one ends.
class TierWriter {
public:
    TierWriter(std::string tier, const FrameGrid& grid, std::vector<Annotation>& out)
        : tier_(std::move(tier)), grid_(&grid), out_(&out) {}
    void add(double startSeconds, double endSeconds, const std::string& value) {
        std::int64_t first = std::max(grid_->frameOf(startSeconds), lastFrame_);
        std::int64_t last = std::max(grid_->frameOf(endSeconds), first + 1);
        out_->push_back({tier_, grid_->ms(first), grid_->ms(last), value});
        lastFrame_ = last;
    }

private:
    std::string tier_;
    const FrameGrid* grid_;
    std::vector<Annotation>* out_;
    std::int64_t lastFrame_ = 0;
};

bool writtenItem(const TimelineSpan& span) {
    switch (span.kind) {
        case SpanKind::Sign:
        case SpanKind::Name:
        case SpanKind::Pointing:
        case SpanKind::Fingerspelling:
        case SpanKind::Verb: return true;
        case SpanKind::Hold: return span.item >= 0;  // a HOLD of the gloss; not a boundary hold
        case SpanKind::Rest: return false;
    }
    return false;
}

std::string attribute(const std::string& name, const std::string& value) {
    return " " + name + "=\"" + escapeHtml(value) + "\"";
}

}  // namespace

std::vector<SpelledLetter> spelledLetters(const Timeline& timeline, const TimelineSpan& span) {
    std::vector<const TimelineKey*> keys;
    for (const TimelineKey& k : timeline.right)
        if (k.timeSeconds >= span.keysStartSeconds - 1e-9 && k.timeSeconds <= span.keysEndSeconds + 1e-9) keys.push_back(&k);
    std::string letters = span.label.rfind("fs-", 0) == 0 ? span.label.substr(3) : span.label;
    const bool written = static_cast<int>(letters.size()) == span.letters &&
                         std::all_of(letters.begin(), letters.end(), [](char c) { return isCapital(c); });
    if (!written) {
        // A name spelled other than its gloss: the keys' handshapes, two keys a letter.
        letters.clear();
        for (std::size_t i = 0; i < keys.size(); i += 2) {
            const std::string& shape = keys[i]->handshape;
            letters += shape.size() == 1 && isCapital(shape[0]) ? shape[0] : '?';
        }
        letters.resize(static_cast<std::size_t>(std::max(0, span.letters)), '?');
    }
    std::vector<SpelledLetter> out;
    std::size_t cursor = 0;
    bool readable = true;
    for (char letter : letters) {
        const std::size_t n = keysOfLetter(letter);
        if (cursor + n > keys.size()) {
            readable = false;
            break;
        }
        for (std::size_t i = cursor; i < cursor + n; ++i)
            readable = readable && (letter == '?' || keys[i]->handshape == shapeOfLetter(letter));
        out.push_back({letter, keys[cursor]->timeSeconds, keys[cursor + n - 1]->timeSeconds});
        cursor += n;
    }
    if (readable && cursor == keys.size()) return out;
    // Not the builder's pattern: the span's keys shared out evenly.
    out.clear();
    const double length = (span.keysEndSeconds - span.keysStartSeconds) / static_cast<double>(std::max<std::size_t>(1, letters.size()));
    for (std::size_t i = 0; i < letters.size(); ++i)
        out.push_back({letters[i], span.keysStartSeconds + length * static_cast<double>(i),
                       span.keysStartSeconds + length * static_cast<double>(i + 1)});
    return out;
}

std::string elanDocument(const std::vector<ElanPanel>& panels, const ElanDocumentOptions& options) {
    const FrameGrid grid(options.framesPerSecond);
    std::vector<Annotation> annotations;
    // Tier id -> linguistic type, in the order the tiers are written.
    std::vector<std::pair<std::string, std::string>> tiers;

    // The tiers every panel shares come from the first panel the signer signs (a side-by-side
    // clip's panel of a lab's recording has no timeline).
    const Timeline* first = nullptr;
    for (const ElanPanel& panel : panels)
        if (!first) first = panel.timeline;
    if (first) {
        // Sentences: from the first item's keys to the last's.
        tiers.emplace_back("sentences", "sentence");
        std::map<int, std::pair<double, double>> sentenceTimes;
        std::map<int, std::string> madeGloss;
        for (const TimelineSpan& span : first->spans) {
            if (span.sentence < 0 || !writtenItem(span)) continue;
            auto [it, fresh] = sentenceTimes.try_emplace(span.sentence, span.keysStartSeconds, span.keysEndSeconds);
            if (!fresh) it->second.second = std::max(it->second.second, span.keysEndSeconds);
            std::string& gloss = madeGloss[span.sentence];
            gloss += (gloss.empty() ? "" : " ") + span.label;
        }
        TierWriter sentences("sentences", grid, annotations);
        for (const auto& [sentence, times] : sentenceTimes) {
            const auto index = static_cast<std::size_t>(sentence);
            sentences.add(times.first, times.second,
                          index < options.sentenceGlosses.size() ? options.sentenceGlosses[index] : madeGloss[sentence]);
        }

        tiers.emplace_back("signs", "gloss");
        TierWriter signs("signs", grid, annotations);
        for (const TimelineSpan& span : first->spans)
            if (writtenItem(span)) signs.add(span.keysStartSeconds, span.keysEndSeconds, span.label);

        tiers.emplace_back("fingerspelling", "letter");
        TierWriter letters("fingerspelling", grid, annotations);
        for (const TimelineSpan& span : first->spans)
            if (span.letters > 0 && (span.kind == SpanKind::Fingerspelling || span.kind == SpanKind::Name))
                for (const SpelledLetter& l : spelledLetters(*first, span))
                    letters.add(l.startSeconds, l.endSeconds, std::string(1, l.letter));
    }

    for (const ElanPanel& panel : panels) {
        if (!panel.timeline) continue;
        const std::string tier = panel.label.empty() ? "verb" : "verb " + panel.label;
        tiers.emplace_back(tier, "verb");
        TierWriter verbs(tier, grid, annotations);
        for (const TimelineSpan& span : panel.timeline->spans)
            if (span.kind == SpanKind::Verb)
                verbs.add(span.startSeconds, span.endSeconds, span.label + " (" + panel.timeline->version + ")");
    }

    if (first) {
        // Non-manual spans, overlapping ones on further tiers.
        std::vector<TierWriter> layers;
        std::vector<std::int64_t> layerEnds;
        std::vector<NonManualSpan> spans = first->nonManualSpans;
        std::stable_sort(spans.begin(), spans.end(),
                         [](const NonManualSpan& a, const NonManualSpan& b) { return a.startSeconds < b.startSeconds; });
        tiers.emplace_back("non-manual", "non-manual");
        layers.emplace_back("non-manual", grid, annotations);
        layerEnds.push_back(0);
        for (const NonManualSpan& s : spans) {
            const std::int64_t start = grid.frameOf(s.startSeconds);
            std::size_t layer = 0;
            while (layer < layers.size() && layerEnds[layer] > start) ++layer;
            if (layer == layers.size()) {
                const std::string tier = "non-manual " + std::to_string(layer + 1);
                tiers.emplace_back(tier, "non-manual");
                layers.emplace_back(tier, grid, annotations);
                layerEnds.push_back(0);
            }
            layers[layer].add(s.startSeconds, s.endSeconds, s.text.empty() ? s.marker : s.marker + ": " + s.text);
            layerEnds[layer] = std::max(grid.frameOf(s.endSeconds), start + 1);
        }
    }

    // Time slots: two per annotation, numbered in time order (ties: in the order made).
    struct Slot {
        std::int64_t ms;
        std::size_t annotation;
        bool end;
    };
    std::vector<Slot> slots;
    for (std::size_t i = 0; i < annotations.size(); ++i) {
        slots.push_back({annotations[i].startMs, i, false});
        slots.push_back({annotations[i].endMs, i, true});
    }
    std::stable_sort(slots.begin(), slots.end(), [](const Slot& a, const Slot& b) { return a.ms < b.ms; });
    std::vector<std::size_t> startSlot(annotations.size()), endSlot(annotations.size());
    for (std::size_t s = 0; s < slots.size(); ++s) (slots[s].end ? endSlot : startSlot)[slots[s].annotation] = s + 1;

    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml += "<ANNOTATION_DOCUMENT AUTHOR=\"signstim\" DATE=\"1970-01-01T00:00:00+00:00\" FORMAT=\"3.0\" VERSION=\"3.0\""
           " xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\""
           " xsi:noNamespaceSchemaLocation=\"http://www.mpi.nl/tools/elan/EAFv3.0.xsd\">\n";
    xml += "    <HEADER MEDIA_FILE=\"\" TIME_UNITS=\"milliseconds\">\n";
    xml += "        <MEDIA_DESCRIPTOR" + attribute("MEDIA_URL", options.mediaUrl) + attribute("MIME_TYPE", options.mimeType) +
           attribute("RELATIVE_MEDIA_URL", options.mediaUrl) + "/>\n";
    xml += "        <PROPERTY NAME=\"lastUsedAnnotationId\">" + std::to_string(annotations.size()) + "</PROPERTY>\n";
    xml += "    </HEADER>\n";
    xml += "    <TIME_ORDER>\n";
    for (std::size_t s = 0; s < slots.size(); ++s)
        xml += "        <TIME_SLOT TIME_SLOT_ID=\"ts" + std::to_string(s + 1) + "\" TIME_VALUE=\"" +
               std::to_string(slots[s].ms) + "\"/>\n";
    xml += "    </TIME_ORDER>\n";
    for (const auto& [tier, type] : tiers) {
        bool any = false;
        std::string body;
        for (std::size_t i = 0; i < annotations.size(); ++i) {
            if (annotations[i].tier != tier) continue;
            any = true;
            body += "        <ANNOTATION>\n            <ALIGNABLE_ANNOTATION ANNOTATION_ID=\"a" + std::to_string(i + 1) +
                    "\" TIME_SLOT_REF1=\"ts" + std::to_string(startSlot[i]) + "\" TIME_SLOT_REF2=\"ts" +
                    std::to_string(endSlot[i]) + "\">\n                <ANNOTATION_VALUE>" + escapeHtml(annotations[i].value) +
                    "</ANNOTATION_VALUE>\n            </ALIGNABLE_ANNOTATION>\n        </ANNOTATION>\n";
        }
        xml += "    <TIER" + attribute("LINGUISTIC_TYPE_REF", type) + attribute("TIER_ID", tier) + (any ? ">\n" + body + "    </TIER>\n" : "/>\n");
    }
    std::vector<std::string> types;
    for (const auto& entry : tiers)
        if (std::find(types.begin(), types.end(), entry.second) == types.end()) types.push_back(entry.second);
    for (const std::string& type : types)
        xml += "    <LINGUISTIC_TYPE GRAPHIC_REFERENCES=\"false\"" + attribute("LINGUISTIC_TYPE_ID", type) +
               " TIME_ALIGNABLE=\"true\"/>\n";
    xml += "</ANNOTATION_DOCUMENT>\n";
    return xml;
}

}  // namespace signstim::stimuli
