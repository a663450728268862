#include "analysis/report_models.hpp"

#include "analysis/svg.hpp"
#include "analysis/text_format.hpp"
#include "common/number_format.hpp"
#include "stimuli/study/study_exports.hpp"  // escapeHtml

#include <cmath>

namespace signstim::analysis {

namespace {

using nlohmann::json;

std::string h(const std::string& text) { return stimuli::escapeHtml(text); }
std::string orDash(const std::string& text) { return text.empty() ? "&ndash;" : h(text); }
std::string fixed(double value, int decimals) { return orDash(fixedOrEmpty(value, decimals)); }
std::string pValue(double p) { return orDash(formatPValue(p)); }

// The Wald 95% interval's factor: the normal distribution's 0.975 quantile.
constexpr double kZ975 = 1.959963984540054;

std::string oddsRatio(const ModelRow& r) {
    if (!std::isfinite(r.estimate)) return "&ndash;";
    std::string s = formatFixed(std::exp(r.estimate), 2);
    if (std::isfinite(r.stdError))
        s += " [" + formatFixed(std::exp(r.estimate - kZ975 * r.stdError), 2) + ", " +
             formatFixed(std::exp(r.estimate + kZ975 * r.stdError), 2) + "]";
    return s;
}

json number(double value) { return std::isfinite(value) ? json(roundSignificant6(value)) : json(nullptr); }

json rowJson(const ModelRow& r) {
    return {{"term", r.term},           {"estimate", number(r.estimate)}, {"stdError", number(r.stdError)},
            {"statistic", number(r.statistic)}, {"df", number(r.df)},       {"p", number(r.p)},
            {"pHolm", number(r.pHolm)}, {"note", r.note}};
}

json rowsJson(const std::vector<ModelRow>& rows) {
    json list = json::array();
    for (const ModelRow& r : rows) list.push_back(rowJson(r));
    return list;
}

const char* statusName(ModelStatus s) {
    switch (s) {
        case ModelStatus::Skipped: return "not requested";
        case ModelStatus::RMissing: return "R not found";
        case ModelStatus::PackagesMissing: return "R packages missing";
        case ModelStatus::Failed: return "failed";
        case ModelStatus::Ran: return "fitted";
    }
    return "";
}

std::string lrtText(const ModelFit& m) {
    if (!m.hasLrt) return "likelihood-ratio test not available";
    return "&chi;&sup2;(" + formatNumber(m.lrt.df) + ") = " + fixed(m.lrt.statistic, 2) + ", <i>" +
           h(formatP(m.lrt.p)).replace(0, 1, "p</i>");
}

const ModelRow* findPair(const ModelFit& m, const std::string& a, const std::string& b) {
    for (const ModelRow& r : m.pairs)
        if (r.term == a + " - " + b) return &r;
    return nullptr;
}

}  // namespace

std::string modelPhaseHtml(const StudyAnalysis& a, const Comparison& ranks, const MixedModels& models,
                           const std::string& modelName) {
    const bool glmm = modelName == "comprehension";
    const std::string title = glmm ? "Mixed model: logistic GLMM (lme4::glmer)" : "Mixed model: cumulative-link mixed model (ordinal::clmm)";
    const ModelFit* m = models.ran() ? models.find(modelName) : nullptr;
    if (!m)
        return "<h3>" + title + "</h3>\n<p class=\"note\">Not fitted (" + h(statusName(models.status)) +
               "): see <a href=\"#models\">Mixed models</a>.</p>\n";
    std::string s = "<h3>" + title + "</h3>\n<p><code>" + h(m->formula) + "</code>, " + h(m->family) + "; ";
    for (const ModelRow& r : m->info) s += h(r.term) + " " + fixed(r.estimate, 0) + ", ";
    s += "reference version <b>" + h(models.reference) + "</b>.</p>\n";
    if (!m->warnings.empty()) {
        s += "<div class=\"warn\"><b>R warned while fitting this model</b> (estimates may be unreliable; see R&rsquo;s "
             "messages):<ul>\n";
        for (const ModelRow& w : m->warnings)
            s += "<li>" + h(w.term) + ": " + h(w.note) + (std::isfinite(w.estimate) ? " (" + h(significant6(w.estimate)) + ")" : "") +
                 "</li>\n";
        s += "</ul></div>\n";
    }
    if (!m->errors.empty()) {
        s += "<div class=\"warn\"><b>R could not fit this model:</b><ul>\n";
        for (const std::string& e : m->errors) s += "<li>" + h(e) + "</li>\n";
        s += "</ul></div>\n";
        if (m->fixed.empty()) return s;
    }
    const KruskalWallisResult& kw = ranks.kruskalWallis;
    s += "<p>Versions overall: likelihood-ratio test against the model without version, " + lrtText(*m) +
         " &mdash; beside Kruskal&ndash;Wallis " +
         (kw.defined() ? "<i>H</i>(" + std::to_string(kw.df) + ") = " + formatFixed(kw.h, 2) + ", <i>" +
                             h(formatP(kw.p)).replace(0, 1, "p</i>")
                       : std::string("&ndash;")) +
         ".</p>\n";
    const std::string scale = glmm ? "log odds" : "log cumulative odds";
    const std::string ratio = glmm ? "odds ratio [95% CI]" : "cumulative odds ratio [95% CI]";
    s += "<table><thead><tr><th>term</th><th>estimate (" + scale + ")</th><th>SE</th><th>z</th><th>p</th><th>" + ratio +
         "</th></tr></thead><tbody>\n";
    for (const ModelRow& r : m->fixed)
        s += "<tr><td>" + h(r.term == "(Intercept)" ? r.term + " (" + models.reference + ")" : r.term + " vs " + models.reference) +
             "</td><td>" + fixed(r.estimate, 3) + "</td><td>" + fixed(r.stdError, 3) + "</td><td>" + fixed(r.statistic, 2) +
             "</td><td>" + pValue(r.p) + "</td><td>" + (r.term == "(Intercept)" ? std::string("&ndash;") : oddsRatio(r)) +
             "</td></tr>\n";
    s += "</tbody></table>\n<p class=\"note\">Random intercepts (SD, logit scale): ";
    for (std::size_t i = 0; i < m->random.size(); ++i)
        s += (i ? ", " : "") + h(m->random[i].term) + " " + fixed(m->random[i].estimate, 3);
    s += ". A positive estimate: " +
         std::string(glmm ? "higher odds of a correct answer" : "higher odds of a higher rating (at every threshold)") +
         " than the reference version.</p>\n";

    s += "<table><thead><tr><th>pair</th><th>Mann&ndash;Whitney r</th><th>p (Holm)</th><th>model difference (" + scale +
         ")</th><th>" + ratio + "</th><th>z</th><th>p (Holm)</th></tr></thead><tbody>\n";
    for (const PairTest& p : ranks.pairs) {
        const ModelRow* r = findPair(*m, a.versions[p.first], a.versions[p.second]);
        const bool modelSignificant = r && std::isfinite(r->pHolm) && r->pHolm < a.alpha;
        s += std::string(p.significant || modelSignificant ? "<tr class=\"significant\">" : "<tr>") + "<td>" +
             h(a.versions[p.first] + " vs " + a.versions[p.second]) + "</td><td>" + fixed(p.test.rankBiserial, 2) + "</td><td>" +
             pValue(p.pHolm) + "</td>" +
             (r ? "<td>" + fixed(r->estimate, 3) + "</td><td>" + oddsRatio(*r) + "</td><td>" + fixed(r->statistic, 2) +
                      "</td><td>" + pValue(r->pHolm) + "</td>"
                : "<td>&ndash;</td><td>&ndash;</td><td>&ndash;</td><td>&ndash;</td>") +
             "</tr>\n";
    }
    s += "</tbody></table>\n<p class=\"note\">Left: the paper&rsquo;s Mann&ndash;Whitney tests (scores as independent "
         "samples). Right: the model&rsquo;s Wald z test of the two versions&rsquo; difference, Holm-adjusted over the pairs; "
         "a row is shaded when either is below &alpha; = " +
         formatNumber(a.alpha) + ".</p>\n";
    if (!m->thresholds.empty()) {
        s += "<details><summary>Thresholds (cut points between ratings, logit scale)</summary>\n<table><thead><tr><th>"
             "threshold</th><th>estimate</th><th>SE</th></tr></thead><tbody>\n";
        for (const ModelRow& r : m->thresholds)
            s += "<tr><td>" + h(r.term) + "</td><td>" + fixed(r.estimate, 3) + "</td><td>" + fixed(r.stdError, 3) + "</td></tr>\n";
        s += "</tbody></table></details>\n";
    }
    return s;
}

std::string modelsSectionHtml(const MixedModels& models) {
    std::string s = "<h2 id=\"models\">Mixed models</h2>\n";
    if (models.ran()) {
        s += "<p>Fitted with " + h(models.rVersion) + ", lme4 " + h(models.lme4Version) + ", ordinal " + h(models.ordinalVersion) +
             "; reference version <b>" + h(models.reference) + "</b>. ";
    } else {
        s += "<div class=\"warn\"><b>The mixed models were not fitted</b> (" + h(statusName(models.status)) + "): " +
             h(models.message) + "</div>\n<p>";
    }
    s += "The script and its data are in <code>models/</code>: <code>models.R</code> reads <code>comprehension.csv</code> "
         "(one row per question) and <code>ratings.csv</code> (one row per rating of a version) from its own folder. Rerun "
         "it as it is with <code>Rscript models/models.R</code> (it writes <code>models/models-rerun.csv</code>; "
         "<code>models-output.csv</code> holds the numbers shown here). It needs R with the packages lme4 and ordinal.</p>\n"
         "<ul>\n<li><b>Comprehension</b>: logistic GLMM, <code>correct ~ version + (1 | participant) + (1 | story)</code>, "
         "Laplace approximation, bobyqa optimizer.</li>\n"
         "<li><b>Ratings</b>: cumulative-link (proportional odds) mixed model, <code>rating ~ version + (1 | participant) + "
         "(1 | sentence)</code>, logit link, one threshold between each pair of neighbouring ratings given.</li>\n"
         "<li>Unlike the rank tests, these models treat the repeated measures as such: each participant and each story or "
         "sentence has its own random intercept. The likelihood-ratio test compares each model with the same model without "
         "version; pairs of versions are compared by Wald z tests of their difference (Holm over the pairs). Estimates are on "
         "the logit scale; exp(estimate) is an odds ratio (GLMM) or a cumulative odds ratio (CLMM: the odds of a rating above "
         "any threshold).</li>\n<li>R&rsquo;s warnings and messages (convergence, singular fits) are shown with each model, "
         "not hidden. A singular fit (a random-effect SD of 0) is common with few stories or sentences and usually harmless "
         "for the fixed effects; a convergence warning means the estimates should be checked.</li>\n</ul>\n";
    return s;
}

json modelsJson(const MixedModels& models) {
    json out = {{"status", statusName(models.status)}, {"reference", models.reference}};
    if (!models.ran()) {
        out["message"] = models.message;
        return out;
    }
    out["software"] = {{"R", models.rVersion}, {"lme4", models.lme4Version}, {"ordinal", models.ordinalVersion}};
    json list = json::array();
    for (const ModelFit& m : models.models) {
        json warnings = json::array();
        for (const ModelRow& w : m.warnings) warnings.push_back(w.term + ": " + w.note);
        list.push_back({{"name", m.name},
                        {"formula", m.formula},
                        {"family", m.family},
                        {"info", rowsJson(m.info)},
                        {"fixed", rowsJson(m.fixed)},
                        {"thresholds", rowsJson(m.thresholds)},
                        {"random", rowsJson(m.random)},
                        {"fit", rowsJson(m.fit)},
                        {"pairs", rowsJson(m.pairs)},
                        {"likelihoodRatio", m.hasLrt ? rowJson(m.lrt) : json(nullptr)},
                        {"warnings", warnings},
                        {"errors", m.errors}});
    }
    out["models"] = list;
    return out;
}

std::string modelsSummaryLine(const MixedModels& models) {
    if (!models.ran()) return std::string("mixed models not fitted (") + statusName(models.status) + ")";
    std::string s;
    for (const ModelFit& m : models.models) {
        s += (s.empty() ? "" : "; ") + std::string(m.name == "comprehension" ? "GLMM" : "CLMM") + " " + m.name + ": ";
        if (!m.hasLrt) {
            s += "not fitted (R's error in the report)";
            continue;
        }
        s += "LR chi2(" + formatNumber(m.lrt.df) + ") = " + formatFixed(m.lrt.statistic, 2) + ", " + formatP(m.lrt.p);
        if (!m.warnings.empty()) s += ", " + std::to_string(m.warnings.size()) + " warning(s)";
    }
    return "mixed models: " + s;
}

}  // namespace signstim::analysis
