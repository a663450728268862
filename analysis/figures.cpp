#include "analysis/figures.hpp"

#include "analysis/text_format.hpp"
#include "common/number_format.hpp"

#include <algorithm>
#include <cmath>

namespace signstim::analysis {

namespace {

using render::Colour;
using render::DrawDisc;
using render::Drawing;
using render::DrawLine;
using render::DrawRect;
using render::DrawText;
using render::TextAnchor;

const Colour kInk{34, 34, 34};
const Colour kMuted{90, 90, 90};
const Colour kAxis{68, 68, 68};
const Colour kGrid{228, 228, 228};
const Colour kWhite{255, 255, 255};

// At 2 pixels per unit (the PNG) these draw the label font at whole scales 4, 3, 2 and 2.
constexpr double kTitleSize = 16, kTextSize = 12, kSmallSize = 11, kNoteSize = 10;
constexpr double kLeft = 78, kRight = 28, kPlotHeight = 260, kBracketStep = 17;

Colour tint(const Colour& c, double towardsWhite) {
    const auto mix = [towardsWhite](std::uint8_t v) {
        return static_cast<std::uint8_t>(std::lround(v + (255.0 - v) * towardsWhite));
    };
    return {mix(c.r), mix(c.g), mix(c.b)};
}

Colour shade(const Colour& c, double towardsBlack) {
    const auto mix = [towardsBlack](std::uint8_t v) { return static_cast<std::uint8_t>(std::lround(v * (1.0 - towardsBlack))); };
    return {mix(c.r), mix(c.g), mix(c.b)};
}

struct Axis {  // a value axis, drawn vertically
    double minimum = 0, maximum = 1, step = 0.2;
    bool percent = false;
    std::string label;
    double top = 0, bottom = 0;  // plot area in units
    double padBottom = 0;        // the minimum this far above the plot's bottom edge
    static constexpr double kPadTop = 10;  // the maximum this far below the top: marks at it stay whole
    double y(double value) const {
        const double clamped = std::clamp(value, minimum, maximum);
        const double high = top + kPadTop, low = bottom - padBottom;
        return low - (clamped - minimum) / (maximum - minimum) * (low - high);
    }
    std::string tick(double value) const { return percent ? analysis::percent(value) : formatNumber(value); }
};

void text(Drawing& d, double x, double y, const std::string& s, double size, TextAnchor anchor = TextAnchor::Start,
          const Colour& colour = kInk, bool bold = false) {
    d.items.push_back(DrawText{x, y, s, size, colour, anchor, bold, false});
}

double textWidth(const std::string& s, double size) { return render::drawingTextWidth(s, size, kFigurePixelsPerUnit); }

// `text` in lines no wider than `width` (breaking at spaces; a word longer than a line stays whole).
std::vector<std::string> wrap(const std::string& text, double size, double width) {
    std::vector<std::string> lines;
    std::string line;
    std::size_t at = 0;
    while (at < text.size()) {
        std::size_t end = text.find(' ', at);
        if (end == std::string::npos) end = text.size();
        const std::string word = text.substr(at, end - at);
        const std::string candidate = line.empty() ? word : line + " " + word;
        if (!line.empty() && textWidth(candidate, size) > width) {
            lines.push_back(line);
            line = word;
        } else {
            line = candidate;
        }
        at = end + 1;
    }
    if (!line.empty()) lines.push_back(line);
    return lines;
}

// Title, subtitle lines, then the plot area's grid and axis; returns nothing, fills `axis.top`.
void frame(Drawing& d, const std::string& title, const std::vector<std::string>& subtitles, Axis& axis, double plotLeft,
           double plotRight) {
    text(d, 16, 24, title, kTitleSize, TextAnchor::Start, kInk, true);
    double y = 24;
    for (const std::string& s : subtitles) text(d, 16, y += 16, s, kSmallSize, TextAnchor::Start, kMuted);
    const int ticks = static_cast<int>(std::lround((axis.maximum - axis.minimum) / axis.step));
    for (int i = 0; i <= ticks; ++i) {
        const double value = axis.minimum + i * axis.step;
        const double ty = std::round(axis.y(value)) + 0.5;
        d.items.push_back(DrawLine{plotLeft, ty, plotRight, ty, kGrid, 1});
        d.items.push_back(DrawLine{plotLeft - 5, ty, plotLeft, ty, kAxis, 1});
        text(d, plotLeft - 8, ty + 4, axis.tick(value), kSmallSize, TextAnchor::End, kInk);
    }
    d.items.push_back(DrawLine{plotLeft - 0.5, axis.top, plotLeft - 0.5, axis.bottom + 0.5, kAxis, 1});
    d.items.push_back(DrawLine{plotLeft - 0.5, axis.bottom + 0.5, plotRight, axis.bottom + 0.5, kAxis, 1});
    d.items.push_back(DrawText{plotLeft - kLeft + 20, (axis.top + axis.bottom) / 2, axis.label, kTextSize, kInk, TextAnchor::Middle,
                               false, true});
}

std::string kruskalLine(const Comparison& c) {
    const KruskalWallisResult& kw = c.kruskalWallis;
    if (!kw.defined()) return "Kruskal-Wallis: not defined (fewer than two versions with data)";
    if (kw.allTied) return "Kruskal-Wallis: every score is the same (H = 0, p = 1)";
    return "Kruskal-Wallis H(" + std::to_string(kw.df) + ") = " + formatFixed(kw.h, 2) + ", " + formatP(kw.p) +
           ", epsilon^2 = " + formatFixed(kw.epsilonSquared, 3) + "; N = " + std::to_string(kw.n);
}

std::string starLegend(double alpha) {
    return "* / ** / ***: Holm-adjusted Mann-Whitney p < " + formatNumber(alpha) + " / " + formatNumber(alpha / 5) + " / " +
           formatNumber(alpha / 50) + " (Kruskal-Wallis p < " + formatNumber(alpha) + ")";
}

std::string nText(const std::vector<std::size_t>& ns) {
    if (ns.empty()) return "";
    const auto [low, high] = std::minmax_element(ns.begin(), ns.end());
    return *low == *high ? "n = " + std::to_string(*low) : "n = " + std::to_string(*low) + "-" + std::to_string(*high);
}

struct BoxSpec {
    std::string name, title, caption;
    Axis axis;
    std::string measureNote;  // what one score is
};

Figure boxPlotFigure(const StudyAnalysis& a, const Comparison& c, BoxSpec spec) {
    const std::size_t versions = a.versions.size();
    std::vector<const PairTest*> marked;
    for (const PairTest& p : c.pairs)
        if (p.significant) marked.push_back(&p);
    // Short brackets nearest the boxes, long ones above them.
    std::stable_sort(marked.begin(), marked.end(),
                     [](const PairTest* x, const PairTest* y) { return x->second - x->first < y->second - y->first; });

    const double slot = 112;
    const double plotWidth = slot * static_cast<double>(versions);
    const double width = std::max(kLeft + plotWidth + kRight, 16 + textWidth(spec.title, kTitleSize) + 16);
    std::vector<std::string> subtitles = wrap(kruskalLine(c), kSmallSize, width - 32);
    for (const std::string& line : wrap(spec.measureNote, kSmallSize, width - 32)) subtitles.push_back(line);
    const std::vector<std::string> notes =
        wrap("Box: quartiles; bar: median; whiskers: furthest score within 1.5 box lengths; circles: scores beyond; "
             "dot: mean. " + starLegend(a.alpha),
             kNoteSize, width - 32);
    const double plotLeft = kLeft + std::floor((width - kLeft - kRight - plotWidth) / 2);
    const auto centre = [&](std::size_t v) { return plotLeft + slot * (static_cast<double>(v) + 0.5); };
    // Brackets: each on the lowest level where it overlaps no other (short ones first).
    std::vector<std::size_t> level(marked.size(), 0);
    std::size_t levels = 0;
    for (std::size_t i = 0; i < marked.size(); ++i) {
        for (std::size_t l = 0;; ++l) {
            bool free = true;
            for (std::size_t j = 0; j < i; ++j)
                if (level[j] == l && marked[j]->first < marked[i]->second && marked[i]->first < marked[j]->second) free = false;
            if (free) {
                level[i] = l;
                break;
            }
        }
        levels = std::max(levels, level[i] + 1);
    }
    Axis& axis = spec.axis;
    axis.padBottom = 8;
    axis.top = 24 + 16 * subtitles.size() + 16 + kBracketStep * static_cast<double>(levels);
    axis.bottom = axis.top + kPlotHeight;
    Drawing d;
    d.width = width;
    d.height = axis.bottom + 46 + 14 * notes.size() + 10;
    d.title = spec.title;
    frame(d, spec.title, subtitles, axis, plotLeft, plotLeft + plotWidth);

    for (std::size_t v = 0; v < versions; ++v) {
        const Descriptives& ds = c.descriptives[v];
        const double cx = std::round(centre(v));
        const Colour colour = versionColour(a.versions[v]);
        text(d, cx, axis.bottom + 20, a.versions[v], kTextSize, TextAnchor::Middle, kInk, true);
        text(d, cx, axis.bottom + 36, "n = " + std::to_string(ds.n), kSmallSize, TextAnchor::Middle, kMuted);
        if (ds.n == 0) {
            text(d, cx, axis.y((axis.minimum + axis.maximum) / 2), "no data", kSmallSize, TextAnchor::Middle, kMuted);
            continue;
        }
        std::vector<double> sorted = c.scores[v];
        std::sort(sorted.begin(), sorted.end());
        const double spread = ds.q3 - ds.q1;
        double whiskerLow = ds.q1, whiskerHigh = ds.q3;
        for (double s : sorted) {
            if (s >= ds.q1 - 1.5 * spread) whiskerLow = std::min(whiskerLow, s);
            if (s <= ds.q3 + 1.5 * spread) whiskerHigh = std::max(whiskerHigh, s);
        }
        const Colour dark = shade(colour, 0.35);
        const double boxHalf = 24, capHalf = 12;
        // Whiskers under the box.
        d.items.push_back(DrawLine{cx, axis.y(whiskerHigh), cx, axis.y(ds.q3), dark, 1.5});
        d.items.push_back(DrawLine{cx, axis.y(ds.q1), cx, axis.y(whiskerLow), dark, 1.5});
        d.items.push_back(DrawLine{cx - capHalf, axis.y(whiskerHigh), cx + capHalf, axis.y(whiskerHigh), dark, 1.5});
        d.items.push_back(DrawLine{cx - capHalf, axis.y(whiskerLow), cx + capHalf, axis.y(whiskerLow), dark, 1.5});
        const double top = axis.y(ds.q3), bottom = axis.y(ds.q1);
        d.items.push_back(DrawRect{cx - boxHalf, top, 2 * boxHalf, std::max(bottom - top, 1.0), tint(colour, 0.55), dark, 1.5});
        d.items.push_back(DrawLine{cx - boxHalf, axis.y(ds.median), cx + boxHalf, axis.y(ds.median), dark, 3});
        for (double s : sorted)
            if (s < whiskerLow || s > whiskerHigh) d.items.push_back(DrawDisc{cx, axis.y(s), 2.6, kWhite, dark, 1.2});
        d.items.push_back(DrawDisc{cx, axis.y(ds.mean), 4, kWhite, kInk, 1.5});
    }
    for (std::size_t i = 0; i < marked.size(); ++i) {
        const PairTest& p = *marked[i];
        const double y = std::round(axis.top - 8 - kBracketStep * static_cast<double>(level[i])) + 0.5;
        const double x1 = std::round(centre(p.first)) + 3, x2 = std::round(centre(p.second)) - 3;
        d.items.push_back(DrawLine{x1, y, x2, y, kInk, 1});
        d.items.push_back(DrawLine{x1 + 0.5, y, x1 + 0.5, y + 5, kInk, 1});
        d.items.push_back(DrawLine{x2 - 0.5, y, x2 - 0.5, y + 5, kInk, 1});
        text(d, (x1 + x2) / 2, y - 1, significanceStars(p.pHolm, a.alpha), kTextSize, TextAnchor::Middle, kInk, true);
    }
    double y = axis.bottom + 46;
    for (const std::string& n : notes) text(d, 16, y += 14, n, kNoteSize, TextAnchor::Start, kMuted);
    Figure f;
    f.name = spec.name;
    f.title = spec.title;
    f.caption = spec.caption;
    f.drawing = std::move(d);
    return f;
}

struct BarSpec {
    std::string name, title, caption;
    Axis axis;
    std::string measureNote;
};

Figure perVerbFigure(const StudyAnalysis& a, const std::vector<Comparison>& comparisons, BarSpec spec) {
    const std::size_t versions = a.versions.size();
    const double bar = 17, gap = 2, groupGap = 26;
    const double group = versions * bar + (versions - 1) * gap;
    const double plotWidth = static_cast<double>(comparisons.size()) * (group + groupGap);
    const double width = std::max(kLeft + plotWidth + kRight, 16 + textWidth(spec.title, kTitleSize) + 16);
    const std::vector<std::string> subtitles =
        wrap("Mean and 95% confidence interval (t) per verb and version; " + spec.measureNote + ". * over a verb: Kruskal-Wallis p < " +
                 formatNumber(a.alpha) + " across its versions (pairs: report tables).",
             kSmallSize, width - 32);
    const double plotLeft = kLeft + std::floor((width - kLeft - kRight - plotWidth) / 2);
    Axis& axis = spec.axis;
    axis.top = 24 + 16 * subtitles.size() + 30 + 18;  // legend, then a row for the stars
    axis.bottom = axis.top + kPlotHeight;
    Drawing d;
    d.width = width;
    d.height = axis.bottom + 50;
    d.title = spec.title;
    frame(d, spec.title, subtitles, axis, plotLeft, plotLeft + plotWidth);
    // Legend, one swatch per version, in a row above the plot.
    double lx = plotLeft;
    const double ly = axis.top - 30;
    for (std::size_t v = 0; v < versions; ++v) {
        d.items.push_back(DrawRect{lx, ly - 10, 12, 12, versionColour(a.versions[v]), std::nullopt, 1});
        text(d, lx + 17, ly, a.versions[v], kSmallSize, TextAnchor::Start, kInk);
        lx += 17 + textWidth(a.versions[v], kSmallSize) + 18;
    }
    for (std::size_t g = 0; g < comparisons.size(); ++g) {
        const Comparison& c = comparisons[g];
        const double left = std::round(plotLeft + groupGap / 2 + static_cast<double>(g) * (group + groupGap));
        std::vector<std::size_t> ns;
        for (std::size_t v = 0; v < versions; ++v) {
            const Descriptives& ds = c.descriptives[v];
            ns.push_back(ds.n);
            if (ds.n == 0) continue;
            const double x = left + static_cast<double>(v) * (bar + gap);
            const Colour colour = versionColour(a.versions[v]);
            const double top = axis.y(ds.mean);
            d.items.push_back(DrawRect{x, top, bar, std::max(axis.bottom - top, 0.0), colour, std::nullopt, 1});
            if (std::isfinite(ds.ci95Low)) {
                const double cx = x + bar / 2, high = axis.y(ds.ci95High), low = axis.y(ds.ci95Low);
                d.items.push_back(DrawLine{cx, high, cx, low, kInk, 1.2});
                d.items.push_back(DrawLine{cx - 4, high, cx + 4, high, kInk, 1.2});
                d.items.push_back(DrawLine{cx - 4, low, cx + 4, low, kInk, 1.2});
            }
        }
        const double cx = left + group / 2;
        text(d, cx, axis.bottom + 20, c.verb, kTextSize, TextAnchor::Middle, kInk, true);
        text(d, cx, axis.bottom + 36, nText(ns), kNoteSize, TextAnchor::Middle, kMuted);
        if (c.omnibusSignificant) text(d, cx, axis.top - 4, "*", kTextSize, TextAnchor::Middle, kInk, true);
    }
    Figure f;
    f.name = spec.name;
    f.title = spec.title;
    f.caption = spec.caption;
    f.drawing = std::move(d);
    return f;
}

bool hasData(const Comparison& c) {
    for (const Descriptives& d : c.descriptives)
        if (d.n > 0) return true;
    return false;
}

bool anyData(const std::vector<Comparison>& cs) {
    return std::any_of(cs.begin(), cs.end(), [](const Comparison& c) { return hasData(c); });
}

}  // namespace

std::string significanceStars(double p, double alpha) {
    if (!(p < alpha)) return "";
    if (p < alpha / 50) return "***";
    if (p < alpha / 5) return "**";
    return "*";
}

render::Colour versionColour(const std::string& version) {
    if (version == "point") return {0, 114, 178};
    if (version == "vector") return {230, 159, 0};
    if (version == "animator") return {0, 158, 115};
    if (version == "uninflected") return {204, 121, 167};
    return {136, 136, 136};
}

std::vector<Figure> studyFigures(const StudyAnalysis& a) {
    std::vector<Figure> figures;
    const double likertMin = a.likertMinimum, likertMax = a.likertMaximum;
    const double likertStep = likertMax - likertMin > 12 ? std::ceil((likertMax - likertMin) / 10) : 1;
    const std::string scale = std::to_string(a.likertMinimum) + "-to-" + std::to_string(a.likertMaximum);
    if (hasData(a.comprehension))
        figures.push_back(boxPlotFigure(
            a, a.comprehension,
            {"fig6-comprehension", "Figure 6 - Comprehension questions (phase 1)",
             "Each participant's proportion of comprehension questions answered correctly in the stories they saw in each "
             "version (the paper's Figure 6).",
             Axis{0, 1, 0.2, true, "questions answered correctly", 0, 0},
             "one score per participant and version: the share of their questions answered correctly"}));
    if (hasData(a.likert))
        figures.push_back(boxPlotFigure(
            a, a.likert,
            {"fig7-likert", "Figure 7 - Side-by-side ratings (phase 2)",
             "Every " + scale + " rating of the verb's quality in the side-by-side comparisons, per version (the paper's Figure 7).",
             Axis{likertMin, likertMax, likertStep, false, scale + " rating", 0, 0},
             "one score per rating: participant x sentence x version"}));
    if (anyData(a.likertByVerb))
        figures.push_back(perVerbFigure(
            a, a.likertByVerb,
            {"fig8-likert-by-verb", "Figure 8 - Side-by-side ratings per verb (phase 2)",
             "Mean " + scale + " rating per verb and version with its 95% confidence interval (the paper's Figure 8).",
             Axis{likertMin, likertMax, likertStep, false, "mean rating", 0, 0}, "bars start at the scale's lowest point"}));
    if (anyData(a.comprehensionByVerb))
        figures.push_back(perVerbFigure(
            a, a.comprehensionByVerb,
            {"fig8b-comprehension-by-verb", "Figure 8b - Comprehension per verb (phase 1)",
             "Mean per-participant accuracy on the questions about each verb, per version, with its 95% confidence interval "
             "(not in the paper; the questions belong to the verb they ask about).",
             Axis{0, 1, 0.2, true, "questions answered correctly", 0, 0}, "participants' shares of the verb's questions"}));
    return figures;
}

}  // namespace signstim::analysis
