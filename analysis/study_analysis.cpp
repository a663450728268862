#include "analysis/study_analysis.hpp"

#include <cmath>
#include <set>

namespace signstim::analysis {

namespace {

using stimuli::StudyListing;

// Phase 1, one score per participant and version: the proportion of the questions (about
// `verb`, or all when empty) they answered correctly in the stories they saw in that version.
Comparison comprehensionComparison(const StudyListing& study, const std::vector<ParticipantResults>& results,
                                   const std::string& verb, double alpha) {
    const std::size_t versions = study.versions.size();
    std::vector<std::vector<double>> scores(versions);
    std::vector<std::vector<std::string>> sources(versions);
    for (const ParticipantResults& participant : results) {
        std::vector<int> correct(versions, 0), asked(versions, 0);
        for (const Phase1Result& trial : participant.phase1) {
            const stimuli::ListedStory& story = study.stories[trial.story];
            for (std::size_t q = 0; q < trial.correct.size(); ++q) {
                if (!verb.empty() && story.questions[q].probeVerb != verb) continue;
                ++asked[trial.version];
                correct[trial.version] += trial.correct[q] ? 1 : 0;
            }
        }
        for (std::size_t v = 0; v < versions; ++v) {
            if (asked[v] == 0) continue;
            scores[v].push_back(static_cast<double>(correct[v]) / static_cast<double>(asked[v]));
            sources[v].push_back(participant.participant);
        }
    }
    Comparison c = compareVersions(std::move(scores), std::move(sources), alpha);
    c.phase = 1;
    c.verb = verb;
    c.measure = "proportion correct";
    c.id = verb.empty() ? "phase1-comprehension" : "phase1-comprehension-verb-" + verb;
    return c;
}

// Phase 2, one score per participant, sentence and version: the rating.
Comparison likertComparison(const StudyListing& study, const std::vector<ParticipantResults>& results,
                            const std::string& verb, double alpha) {
    const std::size_t versions = study.versions.size();
    std::vector<std::vector<double>> scores(versions);
    std::vector<std::vector<std::string>> sources(versions);
    for (const ParticipantResults& participant : results)
        for (const Phase2Result& trial : participant.phase2) {
            const stimuli::ListedSentence& sentence = study.sentences[trial.sentence];
            if (!verb.empty() && sentence.verb != verb) continue;
            for (std::size_t v = 0; v < versions; ++v) {
                if (std::isnan(trial.ratings[v])) continue;
                scores[v].push_back(trial.ratings[v]);
                sources[v].push_back(participant.participant + " " + sentence.id);
            }
        }
    Comparison c = compareVersions(std::move(scores), std::move(sources), alpha);
    c.phase = 2;
    c.verb = verb;
    c.measure = "rating";
    c.id = verb.empty() ? "phase2-likert" : "phase2-likert-verb-" + verb;
    return c;
}

}  // namespace

Comparison compareVersions(std::vector<std::vector<double>> scores, std::vector<std::vector<std::string>> sources,
                           double alpha) {
    Comparison c;
    c.scores = std::move(scores);
    c.sources = std::move(sources);
    for (const std::vector<double>& s : c.scores) c.descriptives.push_back(describe(s));
    c.kruskalWallis = kruskalWallis(c.scores);
    c.omnibusSignificant = c.kruskalWallis.defined() && c.kruskalWallis.p < alpha;
    std::vector<double> p;
    for (std::size_t a = 0; a < c.scores.size(); ++a)
        for (std::size_t b = a + 1; b < c.scores.size(); ++b) {
            PairTest pair;
            pair.first = a;
            pair.second = b;
            pair.test = mannWhitney(c.scores[a], c.scores[b]);
            p.push_back(pair.test.p);
            c.pairs.push_back(pair);
        }
    const std::vector<double> adjusted = holmAdjust(p);
    for (std::size_t i = 0; i < c.pairs.size(); ++i) {
        c.pairs[i].pHolm = adjusted[i];
        c.pairs[i].significant = c.omnibusSignificant && !std::isnan(adjusted[i]) && adjusted[i] < alpha;
    }
    return c;
}

StudyAnalysis analyzeStudy(const StudyListing& study, const std::vector<ParticipantResults>& results,
                           const AnalysisSettings& settings) {
    StudyAnalysis a;
    a.versions = study.versions;
    a.alpha = settings.alpha;
    a.likertMinimum = study.likertMinimum;
    a.likertMaximum = study.likertMaximum;
    a.participantsInStudy = study.participants.size();
    a.participantsWithData = results.size();
    for (const ParticipantResults& r : results) a.synthetic = a.synthetic || r.synthetic;
    a.comprehension = comprehensionComparison(study, results, "", settings.alpha);
    a.likert = likertComparison(study, results, "", settings.alpha);
    std::set<std::string> questionVerbs, sentenceVerbs;
    for (const stimuli::ListedStory& story : study.stories)
        for (const stimuli::ListedQuestion& q : story.questions)
            if (!q.probeVerb.empty()) questionVerbs.insert(q.probeVerb);
    for (const stimuli::ListedSentence& s : study.sentences) sentenceVerbs.insert(s.verb);
    for (const std::string& verb : questionVerbs)
        a.comprehensionByVerb.push_back(comprehensionComparison(study, results, verb, settings.alpha));
    for (const std::string& verb : sentenceVerbs) a.likertByVerb.push_back(likertComparison(study, results, verb, settings.alpha));
    return a;
}

}  // namespace signstim::analysis
