#include "app/study_runner.hpp"

#include "app/cli_values.hpp"
#include "app/progress.hpp"
#include "app/study_questions.hpp"
#include "app/study_units.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/file_manifest.hpp"
#include "signer/avatar_render.hpp"
#include "signer/signer.hpp"
#include "signer/signer_reach.hpp"
#include "signer/timeline_clip.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/scenes_path.hpp"
#include "stimuli/study/study_experiment.hpp"
#include "stimuli/study/study_folder_lock.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#ifndef SIGNSTIM_VERSION
#define SIGNSTIM_VERSION "0.0.0"
#endif

namespace signstim::app {

using namespace signstim::stimuli;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// A story file the study names must exist: say so at the study file's line, not only the path.
Story loadNamedStory(const StoryWorld& world, const StudyFile& study, const StudyFile::StoryEntry& entry,
                     const std::string& field) {
    try {
        return world.loadStory(entry.path);
    } catch (const InputError& e) {
        if (e.file() == entry.path.string() && e.line() == 0)
            throw InputError(study.file, entry.line, field, "\"" + entry.written + "\" (" + entry.path.string() + "): " + e.detail());
        throw;
    }
}

LoadedStudy loadStudy(const StudyRunOptions& options) {
    LoadedStudy s;
    const fs::path scenes = resolveScenesDir(options.scenesDir);
    const fs::path studyFile = options.studyFile.empty() ? defaultStudyFile(scenes) : options.studyFile;
    s.study = loadStudyFile(studyFile);
    s.world = std::make_unique<StoryWorld>(options.scenesDir, options.lexicon);
    // Issue 21: transitions paced by the path the default signer's hands take (detours
    // included), the same whatever avatar renders them.
    const auto pacingSigner = std::make_shared<const signer::Signer>(s.world->scenes);
    s.world->transitionPacer = signer::transitionPacer(pacingSigner);
    // Issue 21: verbs signed within the default signer's comfortable reach, whatever avatar renders them.
    s.world->reach = signer::signerReach(pacingSigner->rig());
    const StudyFile& study = s.study;
    for (std::size_t i = 0; i < study.stories.size(); ++i) {
        Story story = loadNamedStory(*s.world, study, study.stories[i], "/stories/" + std::to_string(i));
        if (story.questions.empty())
            throw InputError(study.file, study.stories[i].line, "/stories/" + std::to_string(i),
                             "\"" + study.stories[i].written +
                                 "\" has no questions: a phase-1 story needs its comprehension questions (docs/stories.md)");
        s.stories.push_back(std::move(story));
    }
    if (!study.phase2Story.path.empty()) {
        s.phase2 = loadNamedStory(*s.world, study, study.phase2Story, "/phase2/story");
        if (s.study.phase2Sentences.empty())
            for (std::size_t i = 0; i < s.phase2->sentences.size(); ++i) s.study.phase2Sentences.push_back(static_cast<int>(i));
        for (std::size_t i = 0; i < s.study.phase2Sentences.size(); ++i) {
            const int n = s.study.phase2Sentences[i];
            if (n >= static_cast<int>(s.phase2->sentences.size()))
                throw InputError(study.file, study.phase2Line, "/phase2/sentences/" + std::to_string(i),
                                 "sentence " + std::to_string(n + 1) + " does not exist: \"" + study.phase2Story.written +
                                     "\" has " + std::to_string(s.phase2->sentences.size()));
            const StorySentence& sentence = s.phase2->sentences[static_cast<std::size_t>(n)];
            const auto verbs = std::count_if(sentence.items.begin(), sentence.items.end(),
                                             [](const StoryItem& item) { return item.kind == StoryItemKind::Verb; });
            if (verbs != 1)
                throw InputError(s.phase2->file, sentence.line, "/sentences/" + std::to_string(n),
                                 "a phase-2 sentence shows one verb in every version; \"" + sentence.gloss + "\" has " +
                                     std::to_string(verbs));
        }
    }
    if (const std::string problem = designProblem(s.study.designSpec()); !problem.empty())
        throw InputError(study.file, study.phase2Line, "/phase2", "this design cannot be built: " + problem);

    s.settings = options.quick ? study.quick : study.render;
    const std::string fpsField = options.quick ? "/quick/fps" : "/render/fps";
    try {
        s.frameRate = render::parseFrameRate(s.settings.fps, study.file, fpsField);
    } catch (const InputError& e) {
        throw InputError(study.file, s.settings.fpsLine, fpsField, e.detail());
    }
    s.pngFrames = options.pngFrames || study.pngFrames;
    prepareSignedText(s);  // issue 24: questions and instructions in ASL
    s.experiment = options.experiment.empty() ? study.experiment : options.experiment;  // may still be "" or "none"
    s.listing = planStudy(s.study, s.stories, s.phase2 ? &*s.phase2 : nullptr, SIGNSTIM_VERSION, s.pngFrames);
    // Draft animator files (issue 22): refused unless --allow-draft-animator; listed either way.
    s.world->allowDraftAnimator = options.allowDraftAnimator;
    if (std::count(s.study.versions.begin(), s.study.versions.end(), VerbVersion::Animator) > 0) {
        for (const Story& story : s.stories)
            for (const std::string& f : s.world->draftAnimatorFiles(story)) s.listing.draftAnimator.push_back(f);
        if (s.phase2)
            for (const std::string& f : s.world->draftAnimatorFiles(*s.phase2)) s.listing.draftAnimator.push_back(f);
        std::sort(s.listing.draftAnimator.begin(), s.listing.draftAnimator.end());
        s.listing.draftAnimator.erase(std::unique(s.listing.draftAnimator.begin(), s.listing.draftAnimator.end()),
                                      s.listing.draftAnimator.end());
        if (!s.listing.draftAnimator.empty() && !options.allowDraftAnimator)
            throw InputError(s.listing.draftAnimator.front(), readJsonFile(s.listing.draftAnimator.front()).lineAt("/draft"),
                             "/draft",
                             std::to_string(s.listing.draftAnimator.size()) + " animator file" +
                                 (s.listing.draftAnimator.size() == 1 ? " is a draft" : "s are drafts") +
                                 " (\"draft\": true), starting points no animator has worked on; finish them and delete "
                                 "\"draft\", or pass --allow-draft-animator (the manifest and review page then list them)");
        for (std::string& f : s.listing.draftAnimator) f = fs::path(f).filename().string();  // as in scenes/animator/
    }
    // The plan must not depend on where the study file was named from (shards, merges).
    s.listing.studyFile = fs::path(study.file).filename().string();
    s.listing.size = std::to_string(s.settings.width) + "x" + std::to_string(s.settings.height);
    s.listing.fps = s.frameRate.text();
    s.listing.msaa = s.settings.msaa;

    const fs::path& data = s.world->scenes;
    s.dataHash = studyDataHash(SIGNSTIM_VERSION, s.settings, s.pngFrames, s.listing.versions,
                               studyInputs(data, s.world->lexiconPath, s.world->labLexiconPath,
                                           signer::defaultAvatarPath(data)));
    s.units = studyUnits(s.listing);
    // Probed now: a bad recording fails before any frame. A recording this folder has probed
    // before (the same bytes) is not decoded again (app/study_human.hpp).
    HumanProbeCache probes = options.out.empty() ? HumanProbeCache{} : readHumanProbeCache(options.out);
    s.humanClips = loadHumanClips(s.study, s.listing, probes);
    return s;
}

std::vector<VerbVersion> studyVersions(const LoadedStudy& s) { return s.study.versions; }

// Settles whether the experiment is written: the command line, else the study file, else what the
// run that wrote `previous` (the folder's plan) decided, so that a resumed or repeated run keeps
// it. Checks that the study fits the experiment's results: columns q1 ... q4 (docs/experiment.md),
// said now rather than after the clips.
void useExperiment(LoadedStudy& s, const std::string& previous) {
    if (s.experiment.empty()) s.experiment = previous;
    if (s.experiment == "none") s.experiment.clear();
    if (s.experiment.empty()) return;
    const StudyFile& study = s.study;
    for (std::size_t i = 0; i < s.stories.size(); ++i)
        if (s.stories[i].questions.size() > kExperimentMaxQuestions)
            throw InputError(study.file, study.stories[i].line, "/stories/" + std::to_string(i),
                             "\"" + study.stories[i].written + "\" has " + std::to_string(s.stories[i].questions.size()) +
                                 " questions; the jsPsych experiment's results have columns for " +
                                 std::to_string(kExperimentMaxQuestions) +
                                 " (q1-q4): give each story at most 4, or leave out the experiment");
}

// The story a unit tells: a phase-1 story whole, or the one phase-2 sentence.
Story unitStory(const LoadedStudy& s, const StudyUnit& unit) {
    if (unit.story) return s.stories[unit.index];
    Story one = *s.phase2;
    const StorySentence sentence = one.sentences[static_cast<std::size_t>(s.study.phase2Sentences[unit.index])];
    one.sentences = {sentence};
    one.questions.clear();
    return one;
}

std::vector<Timeline> unitTimelines(const LoadedStudy& s, const Story& story);

// A unit's timelines: a story's or sentence's in every version, or (issue 24) one per signed
// question or instruction clip.
std::vector<Timeline> timelinesOfUnit(const LoadedStudy& s, const StudyUnit& unit) {
    if (unit.kind != StudyUnitKind::Stimulus) return signedTextTimelines(s, unit);
    return unitTimelines(s, unitStory(s, unit));
}

std::vector<Timeline> unitTimelines(const LoadedStudy& s, const Story& story) {
    TimelineSources sources = s.world->sources(story);
    sources.slotVersions = studyVersions(s);
    // The study's `timing` replaces the story's own (stimuli/story/timing.hpp).
    TimelineOptions timing =
        timelineOptionsFor(s.settings.timing.given() ? s.settings.timing : story.timing, s.settings.rate);
    timing.nonManuals = s.settings.nonManuals;  // issue 23: the study's switch (the story's own holds too)
    std::vector<Timeline> timelines;
    for (VerbVersion v : studyVersions(s)) timelines.push_back(buildTimeline(story, v, sources, timing));
    return timelines;
}


std::uint64_t frameCount(double durationSeconds, double fps) {
    return static_cast<std::uint64_t>(std::floor(durationSeconds * fps + 1e-9)) + 1;
}

json makePlan(const LoadedStudy& s) {
    std::vector<std::string> hashes;
    for (const StudyUnit& u : s.units) {
        const auto human = s.humanClips.find(u.id);
        const std::string hash = unitInputHash(s.dataHash, u, s.study, s.listing);
        hashes.push_back(human == s.humanClips.end() ? hash : withHumanClips(hash, human->second));
    }
    return studyPlan(s.listing, s.settings, s.pngFrames, s.units, hashes, s.experiment);
}

json withoutOutputs(json plan) {
    plan.erase("outputs");
    return plan;
}

// "story-03 (2/12)": the unit being drawn, for the progress line.
std::string unitProgress(const StudyUnit& unit, std::size_t i, std::size_t count) {
    return unit.id + " (" + std::to_string(i + 1) + "/" + std::to_string(count) + ")";
}

}  // namespace

// ---- public ---------------------------------------------------------------------------------------

std::pair<std::size_t, std::size_t> parseShard(const std::string& text) {
    unsigned long index = 0, count = 0;
    char extra = 0;
    if (std::sscanf(text.c_str(), "%lu/%lu%c", &index, &count, &extra) != 2 || count == 0 || index >= count ||
        count > 100000)
        throw commandLineError("--shard", "expected I/N with 0 <= I < N (0-based, as SLURM_ARRAY_TASK_ID of --array=0-(N-1)), got '" + text + "'");
    return {index, count};
}

std::pair<std::size_t, std::size_t> shardFromEnvironment() {
    return parseArrayTaskShard(std::getenv("SLURM_ARRAY_TASK_ID"), std::getenv("SLURM_ARRAY_TASK_COUNT"),
                               std::getenv("SLURM_ARRAY_TASK_MIN"));
}

void checkStudy(const StudyRunOptions& options) {
    LoadedStudy s = loadStudy(options);
    useExperiment(s, "");
    double storySeconds = 0.0, likertSeconds = 0.0;
    std::vector<std::string> notes = s.world->lexiconOverrideNotes();  // authoring notes (story_world.hpp)
    notes.insert(notes.end(), s.signedTextNotes.begin(), s.signedTextNotes.end());
    double signedSeconds = 0.0;
    std::size_t signedClips = 0;
    for (const StudyUnit& unit : s.units) {
        if (unit.kind != StudyUnitKind::Stimulus) {
            for (const Timeline& t : signedTextTimelines(s, unit)) {
                signedSeconds += t.durationSeconds;
                ++signedClips;
            }
            continue;
        }
        const Story story = unitStory(s, unit);
        const std::vector<Timeline> timelines = unitTimelines(s, story);
        (unit.story ? storySeconds : likertSeconds) += timelines.front().durationSeconds;
        if (unit.story)
            for (std::string& note : s.world->fingerspellingNotes(story)) notes.push_back(std::move(note));
    }
    const StudyDesignSpec spec = s.study.designSpec();
    std::printf("%s: ok: \"%s\"\n  %zu stories x %zu versions, %zu participants in %zu groups (each sees every story once, "
                "each version %zu time%s), %zu side-by-side sentences\n  %.0f s of stories per version, %.0f s of side-by-side "
                "clips; design %s\n",
                s.study.file.c_str(), s.study.title.c_str(), spec.stories, spec.versions, spec.participants, spec.versions,
                spec.stories / spec.versions, spec.stories / spec.versions == 1 ? "" : "s", spec.likertTrials, storySeconds, likertSeconds,
                s.listing.designHash.substr(0, 12).c_str());
    for (const HumanVersion& h : s.study.humanVersions) {
        std::size_t recordings = 0;
        for (const auto& unit : s.humanClips)
            for (const HumanClip& clip : unit.second) recordings += clip.name == h.name ? 1 : 0;
        std::printf("  human version \"%s\" (%s): %zu recording%s probed\n", h.name.c_str(),
                    h.phase2Clips.empty() ? "phase 1" : "phases 1 and 2", recordings, recordings == 1 ? "" : "s");
    }
    std::printf("  questions: %s, instructions: %s; %zu signed question and instruction clip%s, %.0f s\n",
                s.study.questionsShown.c_str(), s.study.instructionsShown.c_str(), signedClips, signedClips == 1 ? "" : "s",
                signedSeconds);
    for (const std::string& note : notes) std::printf("note: %s\n", note.c_str());
}

StudyRunReport runStudy(const StudyRunOptions& options) {
    const auto start = Clock::now();
    StudyRunReport report;
    LoadedStudy s = loadStudy(options);
    const fs::path& dir = options.out;
    checkStudyOutFolder(dir, options.force);
    ensureWritableDirectory(dir);
    // From here to the plan written, one run at a time (stimuli/study/study_folder_lock.hpp).
    StudyFolderLock folderLock(dir);
    const std::optional<json> old = hasStudyPlan(dir) ? std::optional<json>(readStudyPlan(dir)) : std::nullopt;
    useExperiment(s, old ? planExperiment(*old) : "");
    // Found and read before the first frame: a missing jsPsych fails now, not after the clips.
    const std::optional<JspsychBundle> jspsych =
        s.experiment.empty() ? std::nullopt : std::optional<JspsychBundle>(loadJspsychBundle());
    const json plan = makePlan(s);
    if (old) {
        // A folder of another study is not overwritten unit by unit: that would mix two studies.
        if (old->at("listing").value("designHash", "") != s.listing.designHash)
            throw InputError(dir.string(), 0, "--out",
                             "holds another study (design " + old->at("listing").value("designHash", "").substr(0, 12) +
                                 ", this one " + s.listing.designHash.substr(0, 12) + "): choose a new folder");
        // The same study with other settings replaces the plan only when no run is rendering the
        // old one into the folder (the shards of one run share it).
        if (withoutOutputs(*old) != withoutOutputs(plan) && folderLock.othersRunning())
            throw EnvironmentError(dir.string() + ": is being rendered by " + folderLock.holder() +
                                   " with other settings; wait for it to finish or choose another folder");
    }
    folderLock.beginRun();
    // What a run killed outright (SIGKILL, a node lost) left behind on this machine.
    if (const std::size_t stale = removeStaleTemporaries(dir); stale > 0 && !options.quiet)
        std::fprintf(stderr, "signstim study: removed %zu temporar%s left by a killed run\n", stale, stale == 1 ? "y" : "ies");
    writeFileAtomic(dir / kStudyPlanFile, plan.dump(2) + "\n");
    writeHumanProbeCache(dir, s.humanClips);

    const std::map<std::string, std::string> hashes = planInputHashes(plan);
    const std::vector<StudyUnit> mine = shardUnits(s.units, options.shardIndex, options.shardCount);
    report.units = s.units.size();
    report.unitsInShard = mine.size();

    // Timelines first (cheap): the frame count for the progress bar, and every verb checked
    // before the first frame.
    const auto timelineStart = Clock::now();
    struct Work {
        StudyUnit unit;
        std::vector<Timeline> timelines;
        double weight = 0.0;  // estimated images to draw: what the progress bar counts
    };
    std::vector<Work> work;
    double totalWeight = 0.0;
    for (const StudyUnit& unit : mine) {
        if (unitComplete(dir, unit.id, hashes.at(unit.id))) {
            ++report.skipped;
            continue;
        }
        Work w{unit, timelinesOfUnit(s, unit), 0};
        if (unit.kind != StudyUnitKind::Stimulus) {
            // Signed questions and instructions: one clip per timeline, each drawn in full.
            for (const Timeline& t : w.timelines)
                w.weight += static_cast<double>(frameCount(t.durationSeconds, s.frameRate.value()));
            totalWeight += w.weight;
            work.push_back(std::move(w));
            continue;
        }
        double duration = 0.0;
        for (const Timeline& t : w.timelines) duration = std::max(duration, t.durationSeconds);
        // A shared frame is drawn once, a frame in a verb slot once per version; a side-by-side
        // frame draws every version's view.
        const double fps = s.frameRate.value();
        const std::uint64_t frames = frameCount(duration, fps);
        const double versions = static_cast<double>(w.timelines.size());
        if (unit.story && options.shareFrames) {
            std::uint64_t inVerbs = 0;
            for (std::uint64_t f = 0; f < frames; ++f) {
                const double t = static_cast<double>(f) / fps;
                for (const TimelineSpan& span : w.timelines.front().spans)
                    if (span.kind == SpanKind::Verb && t >= span.startSeconds && t <= span.endSeconds) {
                        ++inVerbs;
                        break;
                    }
            }
            w.weight = static_cast<double>(frames) + (versions - 1.0) * static_cast<double>(inVerbs);
        } else {
            w.weight = static_cast<double>(frames) * versions;
        }
        totalWeight += w.weight;
        work.push_back(std::move(w));
    }
    report.timelineSeconds = secondsSince(timelineStart);
    if (!work.empty()) {
        // Files the manifest lists are about to change: until this run (or a merge) completes
        // the folder again, it has no manifest and no review page, so it is visibly incomplete.
        removeStaleFile(dir / kStudyManifestFile);
        removeStaleFile(dir / kStudyReviewPage);
    }
    folderLock.unlock();

    if (!work.empty()) {
        UnitRenderer renderer(s, options, dir);
        ProgressReporter progress("signstim study", totalWeight, options.quiet);
        double before = 0.0;
        for (std::size_t i = 0; i < work.size(); ++i) {
            const Work& w = work[i];
            renderer.render(
                w.unit, w.timelines, hashes.at(w.unit.id),
                [&](double fraction) { progress.update(before + fraction * w.weight, unitProgress(w.unit, i, work.size())); },
                report);
            before += w.weight;
            progress.stepDone(before, unitProgress(w.unit, i, work.size()));
            ++report.rendered;
        }
        renderer.finishAll(report);
        progress.end();
    }
    folderLock.lock();
    const auto writeStart = Clock::now();
    const StudyFolderState state = finishStudyFolder(dir, plan, jspsych ? &*jspsych : nullptr);
    report.writeSeconds = secondsSince(writeStart);
    report.complete = state.complete;
    report.experiment = state.experiment;
    report.firstParticipant = state.firstParticipant;
    report.missing = state.missing;
    report.totalSeconds = secondsSince(start);
    return report;
}

}  // namespace signstim::app
