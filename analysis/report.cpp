#include "analysis/report.hpp"

#include "analysis/figure_png.hpp"
#include "analysis/report_models.hpp"
#include "analysis/svg.hpp"
#include "stimuli/study/study_exports.hpp"
#include "analysis/text_format.hpp"
#include "common/number_format.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace signstim::analysis {

namespace {

using nlohmann::json;

// ---- CSV ------------------------------------------------------------------------------------

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string csvRow(const std::vector<std::string>& fields) {
    std::string out;
    for (std::size_t i = 0; i < fields.size(); ++i) out += (i ? "," : "") + csvField(fields[i]);
    return out + "\r\n";
}

std::string number(double value) { return significant6(value); }
std::string count(std::size_t value) { return std::to_string(value); }

// ---- JSON -----------------------------------------------------------------------------------

json jsonNumber(double value) { return std::isfinite(value) ? json(roundSignificant6(value)) : json(nullptr); }

json descriptivesJson(const std::string& version, const Descriptives& d) {
    return {{"version", version},   {"n", d.n},
            {"mean", jsonNumber(d.mean)}, {"sd", jsonNumber(d.sd)},
            {"ci95Low", jsonNumber(d.ci95Low)}, {"ci95High", jsonNumber(d.ci95High)},
            {"median", jsonNumber(d.median)}, {"q1", jsonNumber(d.q1)},
            {"q3", jsonNumber(d.q3)}, {"minimum", jsonNumber(d.minimum)},
            {"maximum", jsonNumber(d.maximum)}};
}

json comparisonJson(const StudyAnalysis& a, const Comparison& c) {
    json versions = json::array();
    for (std::size_t v = 0; v < a.versions.size(); ++v) versions.push_back(descriptivesJson(a.versions[v], c.descriptives[v]));
    const KruskalWallisResult& kw = c.kruskalWallis;
    json pairs = json::array();
    for (const PairTest& p : c.pairs)
        pairs.push_back({{"versionA", a.versions[p.first]},
                         {"versionB", a.versions[p.second]},
                         {"nA", p.test.n1},
                         {"nB", p.test.n2},
                         {"uA", jsonNumber(p.test.u1)},
                         {"z", jsonNumber(p.test.z)},
                         {"p", jsonNumber(p.test.p)},
                         {"pHolm", jsonNumber(p.pHolm)},
                         {"rankBiserial", jsonNumber(p.test.rankBiserial)},
                         {"method", methodName(p.test.method)},
                         {"significant", p.significant}});
    return {{"id", c.id},
            {"phase", c.phase},
            {"verb", c.verb.empty() ? json(nullptr) : json(c.verb)},
            {"measure", c.measure},
            {"versions", versions},
            {"kruskalWallis",
             {{"n", kw.n},
              {"groups", kw.groups},
              {"h", jsonNumber(kw.h)},
              {"df", kw.df},
              {"p", jsonNumber(kw.p)},
              {"epsilonSquared", jsonNumber(kw.epsilonSquared)},
              {"allTied", kw.allTied},
              {"significant", c.omnibusSignificant}}},
            {"pairs", pairs}};
}

// ---- HTML -----------------------------------------------------------------------------------

std::string h(const std::string& text) { return stimuli::escapeHtml(text); }
std::string orDash(const std::string& text) { return text.empty() ? "&ndash;" : h(text); }

std::string pairLabel(const StudyAnalysis& a, const PairTest& p) { return a.versions[p.first] + " vs " + a.versions[p.second]; }

std::string descriptivesTable(const StudyAnalysis& a, const Comparison& c, bool asPercent) {
    const auto value = [&](double v) { return asPercent ? orDash(fixedOrEmpty(v * 100.0, 1)) : orDash(fixedOrEmpty(v, 2)); };
    std::string s = "<table><thead><tr><th>version</th><th>N</th><th>mean</th><th>SD</th><th>95% CI of the mean</th>"
                    "<th>median</th><th>quartiles</th><th>range</th></tr></thead><tbody>\n";
    for (std::size_t v = 0; v < a.versions.size(); ++v) {
        const Descriptives& d = c.descriptives[v];
        s += "<tr><td><span class=\"swatch v-" + h(a.versions[v]) + "\"></span>" + h(a.versions[v]) + "</td><td>" + count(d.n) +
             "</td><td>" + value(d.mean) + "</td><td>" + value(d.sd) + "</td><td>" +
             (std::isfinite(d.ci95Low) ? value(d.ci95Low) + " &ndash; " + value(d.ci95High) : "&ndash;") + "</td><td>" +
             value(d.median) + "</td><td>" + (d.n ? value(d.q1) + " &ndash; " + value(d.q3) : "&ndash;") + "</td><td>" +
             (d.n ? value(d.minimum) + " &ndash; " + value(d.maximum) : "&ndash;") + "</td></tr>\n";
    }
    s += "</tbody></table>\n";
    if (asPercent) s += "<p class=\"note\">Values in per cent of questions answered correctly.</p>\n";
    return s;
}

std::string kruskalSentence(const Comparison& c, double alpha) {
    const KruskalWallisResult& kw = c.kruskalWallis;
    if (!kw.defined()) return "Kruskal&ndash;Wallis: not defined (fewer than two versions with data).";
    if (kw.allTied) return "Kruskal&ndash;Wallis: every score is the same (H = 0, p = 1).";
    return "Kruskal&ndash;Wallis <i>H</i>(" + std::to_string(kw.df) + ") = " + formatFixed(kw.h, 2) + ", <i>" +
           h(formatP(kw.p)).replace(0, 1, "p</i>") + ", &epsilon;&sup2; = " + formatFixed(kw.epsilonSquared, 3) + ", N = " +
           count(kw.n) + ": " +
           (c.omnibusSignificant ? "the versions differ (p &lt; " + formatNumber(alpha) + ")."
                                 : "no significant difference between the versions at &alpha; = " + formatNumber(alpha) + ".");
}

std::string pairsTable(const StudyAnalysis& a, const std::vector<const Comparison*>& comparisons, bool withVerb) {
    std::string s = "<table><thead><tr>" + std::string(withVerb ? "<th>verb</th>" : "") +
                    "<th>pair</th><th>N</th><th>U (first)</th><th>z</th><th>p</th><th>p (Holm)</th>"
                    "<th>rank-biserial r</th><th>p from</th><th></th></tr></thead><tbody>\n";
    for (const Comparison* c : comparisons)
        for (const PairTest& p : c->pairs) {
            const MannWhitneyResult& t = p.test;
            s += std::string(p.significant ? "<tr class=\"significant\">" : "<tr>") + (withVerb ? "<td>" + h(c->verb) + "</td>" : "") +
                 "<td>" + h(pairLabel(a, p)) + "</td><td>" + count(t.n1) + " / " + count(t.n2) + "</td><td>" +
                 orDash(fixedOrEmpty(t.u1, 1)) + "</td><td>" +
                 (t.method == PMethod::Normal ? orDash(fixedOrEmpty(t.z, 2)) : "&ndash;") + "</td><td>" + orDash(formatPValue(t.p)) +
                 "</td><td>" + orDash(formatPValue(p.pHolm)) + "</td><td>" + orDash(fixedOrEmpty(t.rankBiserial, 2)) + "</td><td>" +
                 h(methodName(t.method)) + "</td><td>" + h(significanceStars(p.significant ? p.pHolm : 1.0, a.alpha)) + "</td></tr>\n";
        }
    return s + "</tbody></table>\n";
}

std::string perVerbTable(const StudyAnalysis& a, const std::vector<Comparison>& comparisons, bool asPercent) {
    std::string s = "<table><thead><tr><th>verb</th>";
    for (const std::string& v : a.versions) s += "<th><span class=\"swatch v-" + h(v) + "\"></span>" + h(v) + "<br>mean (N)</th>";
    s += "<th>Kruskal&ndash;Wallis</th><th>&epsilon;&sup2;</th></tr></thead><tbody>\n";
    for (const Comparison& c : comparisons) {
        s += std::string(c.omnibusSignificant ? "<tr class=\"significant\">" : "<tr>") + "<td>" + h(c.verb) + "</td>";
        for (const Descriptives& d : c.descriptives)
            s += "<td>" + (asPercent ? orDash(fixedOrEmpty(d.mean * 100.0, 1)) : orDash(fixedOrEmpty(d.mean, 2))) + " (" +
                 count(d.n) + ")</td>";
        const KruskalWallisResult& kw = c.kruskalWallis;
        s += "<td>" +
             (kw.defined() ? "H(" + std::to_string(kw.df) + ") = " + formatFixed(kw.h, 2) + ", " + h(formatP(kw.p)) : "&ndash;") +
             "</td><td>" + orDash(fixedOrEmpty(kw.epsilonSquared, 3)) + "</td></tr>\n";
    }
    return s + "</tbody></table>\n";
}

std::string figureHtml(const Figure& f) {
    std::string svg = svgElement(f.drawing);
    return "<figure id=\"" + h(f.name) + "\">\n" + svg + "<figcaption><b>" + h(f.title) + ".</b> " + h(f.caption) +
           " <span class=\"files\">Files: <a href=\"figures/" + h(f.name) + ".svg\">SVG</a> &middot; <a href=\"figures/" + h(f.name) +
           ".png\">PNG</a></span></figcaption>\n</figure>\n";
}

const Figure* findFigure(const std::vector<Figure>& figures, const std::string& name) {
    for (const Figure& f : figures)
        if (f.name == name) return &f;
    return nullptr;
}

const char* kStyle = R"(body{font-family:"DejaVu Sans",Verdana,Arial,sans-serif;color:#222;max-width:1100px;margin:24px auto;padding:0 20px;line-height:1.45}
h1{font-size:1.6em;margin-bottom:.2em}h2{margin-top:1.8em;border-bottom:1px solid #ddd;padding-bottom:.2em}h3{margin-top:1.4em}
table{border-collapse:collapse;margin:.6em 0 1em;font-size:.92em}th,td{border:1px solid #d6d6d6;padding:3px 8px;text-align:right;vertical-align:top}
th{background:#f3f3f3}td:first-child,th:first-child,td.text{text-align:left}tr.significant td{background:#fff6d9}
figure{margin:1em 0 1.6em}figure svg{width:100%;max-width:860px;height:auto;border:1px solid #eee}figcaption{font-size:.92em;color:#444;max-width:900px}
.note{font-size:.88em;color:#555}.files{white-space:nowrap}.banner{background:#b00020;color:#fff;padding:10px 14px;font-weight:bold;font-size:1.1em;border-radius:4px}
.swatch{display:inline-block;width:.8em;height:.8em;margin-right:.35em;vertical-align:-.05em}
.v-point{background:#0072b2}.v-vector{background:#e69f00}.v-animator{background:#009e73}.v-uninflected{background:#cc79a7}
ul.checks{font-family:monospace;font-size:.85em}code{font-size:.92em}
.warn{background:#fff0f0;border-left:4px solid #b00020;padding:6px 12px;margin:.6em 0;font-size:.92em}.warn ul{margin:.3em 0}
)";

std::string methodsHtml(const StudyAnalysis& a) {
    const std::string alpha = formatNumber(a.alpha);
    return "<h2 id=\"methods\">Methods</h2>\n<ul>\n"
           "<li><b>Scores.</b> Phase 1: for each participant and version, the proportion of the comprehension questions they "
           "answered correctly in the stories they saw in that version (correctness recomputed from the study's answer keys; "
           "an unanswered question counts as incorrect). Phase 2: every rating of a version in a side-by-side trial, unmapped "
           "from panels A&ndash;D with the sentence's panel code. Per verb: phase-1 questions belong to the verb they ask about "
           "(probeVerb), phase-2 sentences to their verb.</li>\n"
           "<li><b>Kruskal&ndash;Wallis H</b> across the versions, with midranks for ties and the tie correction "
           "(H divided by 1 &minus; &Sigma;(t&sup3;&minus;t)/(N&sup3;&minus;N)); p from the chi-squared distribution with "
           "(versions &minus; 1) degrees of freedom (an approximation, rough below about 5 scores per version). "
           "Effect size &epsilon;&sup2; = H / (N &minus; 1) (Tomczak &amp; Tomczak 2014).</li>\n"
           "<li><b>Mann&ndash;Whitney U</b> for every pair of versions, two-sided. Without ties and with at most " +
           std::to_string(kExactMannWhitneyLimit) +
           " scores in the pair, p is exact (the permutation distribution of U); otherwise from the normal approximation "
           "with the tie-corrected variance n&#8321;n&#8322;/12 &middot; ((N+1) &minus; &Sigma;(t&sup3;&minus;t)/(N(N&minus;1))) "
           "and a continuity correction of 0.5. U is that of the first version of the pair (pairs where it scores higher, ties "
           "counting one half); rank-biserial r = (U&#8321; &minus; U&#8322;)/(n&#8321;n&#8322;), positive when the first "
           "version scores higher (Kerby 2014).</li>\n"
           "<li><b>Multiple comparisons.</b> Holm&rsquo;s step-down correction over the pairs of one comparison (one figure "
           "panel, or one verb). A pair is marked significant (starred, shaded row) when its Holm-adjusted p and the "
           "Kruskal&ndash;Wallis p of its comparison are both below &alpha; = " +
           alpha +
           ". All pairs are listed whatever the omnibus result.</li>\n"
           "<li><b>Descriptives.</b> Mean, sample SD, 95% confidence interval of the mean from Student&rsquo;s t, median and "
           "quartiles by linear interpolation (type 7, as R and numpy).</li>\n"
           "<li><b>Assumptions and caveats.</b> The rank tests treat the scores as independent samples, as the paper did. "
           "The design is within subjects (every participant contributes to every version; in phase 2 each participant "
           "rates several sentences), so the scores are not independent: a participant&rsquo;s overall level is shared by "
           "the versions, which makes these tests conservative for differences between versions, and phase-2 N counts ratings, "
           "not people. The <a href=\"#models\">mixed models</a> model the repeated measures.</li>\n"
           "<li>Distribution functions from Boost.Math; all numbers in results.csv, tests.csv and summary.json to 6 "
           "significant digits.</li>\n</ul>\n";
}

std::string reportHtml(const StudyAnalysis& a, const ReportInputs& in, const std::vector<Figure>& figures) {
    std::string s = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
                    std::string(a.synthetic ? "SYNTHETIC DATA - " : "") + "Analysis: " + h(in.studyTitle) + "</title>\n<style>\n" +
                    kStyle + "</style>\n</head>\n<body>\n";
    if (a.synthetic)
        s += "<p class=\"banner\">SYNTHETIC DATA: these results were made by <code>signstim simulate-results</code>, not "
             "collected from people. Nothing here is a finding.</p>\n";
    s += "<h1>Analysis of " + h(in.studyTitle) + "</h1>\n";
    s += "<p>Study design " + h(in.designHash.substr(0, 12)) + " (" + h(in.manifestName) + "); results of " +
         count(a.participantsWithData) + " of the study&rsquo;s " + count(a.participantsInStudy) + " participants; versions " +
         h([&] {
             std::string v;
             for (const std::string& name : a.versions) v += (v.empty() ? "" : ", ") + name;
             return v;
         }()) +
         "; &alpha; = " + formatNumber(a.alpha) + ". Methods at the <a href=\"#methods\">end</a>.</p>\n";

    // Phase 1.
    s += "<h2>Phase 1: comprehension</h2>\n";
    if (const Figure* f = findFigure(figures, "fig6-comprehension")) {
        s += figureHtml(*f) + descriptivesTable(a, a.comprehension, true) + "<p>" + kruskalSentence(a.comprehension, a.alpha) +
             "</p>\n" + pairsTable(a, {&a.comprehension}, false);
        if (in.models) s += modelPhaseHtml(a, a.comprehension, *in.models, "comprehension");
    } else {
        s += "<p>No phase-1 results.</p>\n";
    }
    s += "<h2>Phase 2: side-by-side ratings</h2>\n";
    if (const Figure* f = findFigure(figures, "fig7-likert")) {
        s += figureHtml(*f) + descriptivesTable(a, a.likert, false) + "<p>" + kruskalSentence(a.likert, a.alpha) + "</p>\n" +
             pairsTable(a, {&a.likert}, false);
        if (in.models) s += modelPhaseHtml(a, a.likert, *in.models, "ratings");
    } else {
        s += "<p>No phase-2 results.</p>\n";
    }
    s += "<h2>Per verb</h2>\n";
    const auto perVerb = [&](const std::string& name, const std::string& heading, const std::vector<Comparison>& cs, bool asPercent) {
        const Figure* f = findFigure(figures, name);
        if (!f) return;
        std::vector<const Comparison*> pointers;
        for (const Comparison& c : cs) pointers.push_back(&c);
        s += "<h3>" + heading + "</h3>\n" + figureHtml(*f) + perVerbTable(a, cs, asPercent) +
             "<details><summary>Pairwise tests per verb (Holm within each verb)</summary>\n" + pairsTable(a, pointers, true) +
             "</details>\n";
    };
    perVerb("fig8-likert-by-verb", "Ratings per verb (phase 2)", a.likertByVerb, false);
    perVerb("fig8b-comprehension-by-verb", "Comprehension per verb (phase 1)", a.comprehensionByVerb, true);

    // Data and checks.
    s += "<h2>Data</h2>\n<table><thead><tr><th>participant</th><th>file</th><th>phase-1 trials</th><th>phase-2 trials</th>"
         "<th>SHA-256</th></tr></thead><tbody>\n";
    for (const ParticipantResults& r : *in.results)
        s += "<tr><td>" + h(r.participant) + (r.synthetic ? " (synthetic)" : "") + "</td><td class=\"text\">" + h(r.fileName) + "</td><td>" +
             count(r.phase1.size()) + "</td><td>" + count(r.phase2.size()) + "</td><td><code>" + h(r.sha256.substr(0, 16)) +
             "&hellip;</code></td></tr>\n";
    s += "</tbody></table>\n";
    if (!in.columnMapName.empty()) s += "<p>Columns renamed by " + h(in.columnMapName) + ".</p>\n";
    s += "<h3>Data checks</h3>\n";
    if (in.warnings.empty()) {
        s += "<p>No problems: every answer&rsquo;s correctness and every rating&rsquo;s version agree with the study, and no "
             "trial is missing.</p>\n";
    } else {
        s += "<p>" + count(in.warnings.size()) +
             " warning(s). The analysis uses the recomputed correctness and the ratings unmapped from the panels.</p>\n<ul "
             "class=\"checks\">\n";
        for (const std::string& w : in.warnings) s += "<li>" + h(w) + "</li>\n";
        s += "</ul>\n";
    }
    if (in.models) s += modelsSectionHtml(*in.models);
    s += methodsHtml(a);
    s += "<h2>Files</h2>\n<p><code>results.csv</code> (descriptives of every cell), <code>tests.csv</code> (every test), "
         "<code>scores.csv</code> (every score tested), <code>summary.json</code> (all of it), <code>figures/</code> (SVG and "
         "PNG), <code>models/</code> (the mixed models&rsquo; R script, its data and R&rsquo;s output).</p>\n</body>\n</html>\n";
    return s;
}

std::vector<const Comparison*> allComparisons(const StudyAnalysis& a) {
    std::vector<const Comparison*> all = {&a.comprehension, &a.likert};
    for (const Comparison& c : a.comprehensionByVerb) all.push_back(&c);
    for (const Comparison& c : a.likertByVerb) all.push_back(&c);
    return all;
}

}  // namespace

std::vector<ReportFile> analysisReport(const StudyAnalysis& a, const ReportInputs& in) {
    const std::vector<Figure> figures = studyFigures(a);
    const std::vector<const Comparison*> comparisons = allComparisons(a);
    std::vector<ReportFile> files;
    files.push_back({"report.html", reportHtml(a, in, figures)});

    const std::string synthetic = a.synthetic ? "# SYNTHETIC DATA (signstim simulate-results): not responses of people\r\n" : "";
    std::string results = synthetic + csvRow({"comparison", "phase", "verb", "measure", "version", "n", "mean", "sd", "ci95_low",
                                              "ci95_high", "median", "q1", "q3", "minimum", "maximum"});
    std::string tests = synthetic + csvRow({"comparison", "phase", "verb", "test", "version_a", "version_b", "n_a", "n_b", "statistic",
                                            "df", "z", "p", "p_holm", "effect_size", "effect_size_measure", "p_method", "significant"});
    std::string scores = synthetic + csvRow({"comparison", "phase", "verb", "version", "source", "score"});
    for (const Comparison* c : comparisons) {
        const std::string phase = std::to_string(c->phase);
        for (std::size_t v = 0; v < a.versions.size(); ++v) {
            const Descriptives& d = c->descriptives[v];
            results += csvRow({c->id, phase, c->verb, c->measure, a.versions[v], count(d.n), number(d.mean), number(d.sd),
                               number(d.ci95Low), number(d.ci95High), number(d.median), number(d.q1), number(d.q3),
                               number(d.minimum), number(d.maximum)});
            for (std::size_t i = 0; i < c->scores[v].size(); ++i)
                scores += csvRow({c->id, phase, c->verb, a.versions[v], c->sources[v][i], number(c->scores[v][i])});
        }
        const KruskalWallisResult& kw = c->kruskalWallis;
        tests += csvRow({c->id, phase, c->verb, "kruskal-wallis", "", "", count(kw.n), "", number(kw.h),
                         kw.defined() ? std::to_string(kw.df) : "", "", number(kw.p), "", number(kw.epsilonSquared),
                         "epsilon_squared", kw.defined() ? (kw.allTied ? "all values tied" : "chi-squared") : "not defined",
                         c->omnibusSignificant ? "1" : "0"});
        for (const PairTest& p : c->pairs)
            tests += csvRow({c->id, phase, c->verb, "mann-whitney", a.versions[p.first], a.versions[p.second], count(p.test.n1),
                             count(p.test.n2), number(p.test.u1), "", p.test.method == PMethod::Normal ? number(p.test.z) : "",
                             number(p.test.p), number(p.pHolm), number(p.test.rankBiserial), "rank_biserial",
                             methodName(p.test.method), p.significant ? "1" : "0"});
    }
    files.push_back({"results.csv", results});
    files.push_back({"tests.csv", tests});
    files.push_back({"scores.csv", scores});

    json summary;
    summary["format"] = "signstim-analysis";
    summary["version"] = 1;
    summary["synthetic"] = a.synthetic;
    summary["study"] = {{"title", in.studyTitle}, {"designHash", in.designHash}, {"manifest", in.manifestName},
                        {"versions", a.versions}, {"likertMinimum", a.likertMinimum}, {"likertMaximum", a.likertMaximum},
                        {"participants", a.participantsInStudy}};
    json inputs = json::array();
    for (const ParticipantResults& r : *in.results)
        inputs.push_back({{"file", r.fileName}, {"participant", r.participant}, {"sha256", r.sha256}, {"synthetic", r.synthetic},
                          {"phase1Trials", r.phase1.size()}, {"phase2Trials", r.phase2.size()}});
    summary["inputs"] = inputs;
    summary["columnMap"] = in.columnMapName.empty() ? json(nullptr) : json(in.columnMapName);
    summary["settings"] = {{"alpha", a.alpha},
                           {"multipleComparisons", "Holm over the pairs of each comparison"},
                           {"pairSignificant", "Holm-adjusted p < alpha and Kruskal-Wallis p < alpha"},
                           {"exactMannWhitneyUpTo", kExactMannWhitneyLimit}};
    summary["warnings"] = in.warnings;
    json comparisonList = json::array();
    for (const Comparison* c : comparisons) comparisonList.push_back(comparisonJson(a, *c));
    summary["comparisons"] = comparisonList;
    json figureList = json::array();
    for (const Figure& f : figures) {
        figureList.push_back({{"name", f.name}, {"title", f.title}, {"svg", "figures/" + f.name + ".svg"},
                              {"png", "figures/" + f.name + ".png"}});
    }
    summary["figures"] = figureList;
    if (in.models) summary["mixedModels"] = modelsJson(*in.models);
    files.push_back({"summary.json", summary.dump(2) + "\n"});

    if (in.modelInputs) {
        files.push_back({"models/models.R", in.modelInputs->script});
        if (!in.modelInputs->comprehensionCsv.empty()) files.push_back({"models/comprehension.csv", in.modelInputs->comprehensionCsv});
        if (!in.modelInputs->ratingsCsv.empty()) files.push_back({"models/ratings.csv", in.modelInputs->ratingsCsv});
    }
    if (in.models && in.models->ran()) files.push_back({"models/models-output.csv", in.models->output});
    for (const Figure& f : figures) {
        files.push_back({"figures/" + f.name + ".svg", svgDocument(f.drawing)});
        const std::vector<std::uint8_t> bytes = figurePng(f.drawing, in.dpi > 0 ? in.dpi : kDefaultFigureDpi);
        files.push_back({"figures/" + f.name + ".png", std::string(bytes.begin(), bytes.end())});
    }
    return files;
}

}  // namespace signstim::analysis
