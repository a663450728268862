#include "app/study_runner.hpp"

#include "app/cli_values.hpp"
#include "app/clip_output.hpp"
#include "stimuli/study/jspsych_bundle.hpp"
#include "stimuli/story/story_world.hpp"
#include "stimuli/study/study_documents.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/sha256.hpp"
#include "renderer/frame_sink.hpp"
#include "renderer/image_io.hpp"
#include "renderer/relay_sinks.hpp"
#include "renderer/renderer.hpp"
#include "renderer/video_encoder.hpp"
#include "signer/avatar_render.hpp"
#include "signer/timeline_clip.hpp"
#include "signer/clip_render.hpp"
#include "signer/signer.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/scenes_path.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/study/study.hpp"
#include "stimuli/study/study_experiment.hpp"
#include "stimuli/story/timeline_builder.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <thread>

#ifndef SIGNSTIM_VERSION
#define SIGNSTIM_VERSION "0.0.0"
#endif

namespace signstim::app {

using namespace signstim::stimuli;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

constexpr const char* kPlanFile = ".signstim/plan.json";
constexpr const char* kUnitFolder = ".signstim/units";
constexpr const char* kManifestFile = "manifest.json";

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// ---- what a study is made of ---------------------------------------------------------------

struct Unit {
    std::string id;      // "likert-03", "story-07": sorted, the order shards are dealt from
    bool story = true;
    std::size_t index = 0;  // story index or phase-2 sentence index
};

struct LoadedStudy {
    StudyFile study;
    std::unique_ptr<StoryWorld> world;
    std::vector<Story> stories;
    std::optional<Story> phase2;
    StudyRenderSettings settings;
    render::FrameRate frameRate;
    bool pngFrames = false;
    std::string experiment;  // "jspsych"; "none" or "": none (decided by useExperiment)
    StudyListing listing;
    std::string dataHash;  // everything every unit depends on
    std::vector<Unit> units;
};

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

void hashFile(Sha256& hash, const fs::path& file) {
    const std::string digest = sha256File(file);
    hash.update(file.filename().string() + " " + digest + "\n");
}

void hashFolder(Sha256& hash, const fs::path& folder) {
    if (!fs::is_directory(folder)) {
        if (fs::exists(folder)) hashFile(hash, folder);
        return;
    }
    std::vector<fs::path> files;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(folder))
        if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const fs::path& f : files) hash.update(f.lexically_relative(folder).generic_string() + " " + sha256File(f) + "\n");
}

LoadedStudy loadStudy(const StudyRunOptions& options) {
    LoadedStudy s;
    const fs::path scenes = resolveScenesDir(options.scenesDir);
    const fs::path studyFile = options.studyFile.empty() ? defaultStudyFile(scenes) : options.studyFile;
    s.study = loadStudyFile(studyFile);
    s.world = std::make_unique<StoryWorld>(options.scenesDir, options.lexicon);
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
    s.experiment = options.experiment.empty() ? study.experiment : options.experiment;  // may still be "" or "none"
    s.listing = planStudy(s.study, s.stories, s.phase2 ? &*s.phase2 : nullptr, SIGNSTIM_VERSION, s.pngFrames);
    // The plan must not depend on where the study file was named from (shards, merges).
    s.listing.studyFile = fs::path(study.file).filename().string();
    s.listing.size = std::to_string(s.settings.width) + "x" + std::to_string(s.settings.height);
    s.listing.fps = s.frameRate.text();
    s.listing.msaa = s.settings.msaa;

    Sha256 hash;
    hash.update(std::string("signstim ") + SIGNSTIM_VERSION + "\n" + s.settings.text() + "\npng " +
                (s.pngFrames ? "yes" : "no") + "\nversions");
    for (const std::string& v : s.listing.versions) hash.update(" " + v);
    hash.update("\n");
    const fs::path& sc = s.world->scenes;
    for (const fs::path& f : {sc / "handshapes.json", sc / "verbs.json", sc / "models" / "verb_models.json",
                              signer::defaultAvatarPath(sc)})
        hashFile(hash, f);
    hashFolder(hash, s.world->lexiconPath);
    hashFolder(hash, sc / "animator");
    s.dataHash = hash.hexDigest();

    for (std::size_t i = 0; i < s.listing.stories.size(); ++i) s.units.push_back({s.listing.stories[i].id, true, i});
    for (std::size_t i = 0; i < s.listing.sentences.size(); ++i) s.units.push_back({s.listing.sentences[i].id, false, i});
    std::sort(s.units.begin(), s.units.end(), [](const Unit& a, const Unit& b) { return a.id < b.id; });
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
Story unitStory(const LoadedStudy& s, const Unit& unit) {
    if (unit.story) return s.stories[unit.index];
    Story one = *s.phase2;
    const StorySentence sentence = one.sentences[static_cast<std::size_t>(s.study.phase2Sentences[unit.index])];
    one.sentences = {sentence};
    one.questions.clear();
    return one;
}

std::vector<Timeline> unitTimelines(const LoadedStudy& s, const Story& story) {
    TimelineSources sources = s.world->sources(story);
    sources.slotVersions = studyVersions(s);
    TimelineOptions timing;
    timing.rate = s.settings.rate;
    std::vector<Timeline> timelines;
    for (VerbVersion v : studyVersions(s)) timelines.push_back(buildTimeline(story, v, sources, timing));
    return timelines;
}

std::string unitInputHash(const LoadedStudy& s, const Unit& unit) {
    Sha256 hash;
    hash.update(s.dataHash + "\n" + unit.id + "\n");
    if (unit.story) {
        hash.update(readTextFile(s.study.stories[unit.index].path));
        for (const ListedClip& c : s.listing.stories[unit.index].clips) hash.update(c.video + "\n");
    } else {
        hash.update(readTextFile(s.study.phase2Story.path));
        const ListedSentence& sentence = s.listing.sentences[unit.index];
        hash.update(std::to_string(s.study.phase2Sentences[unit.index]) + " " + sentence.panelCode + " " +
                    sentence.clip.video + "\n");
    }
    return hash.hexDigest();
}

std::uint64_t frameCount(double durationSeconds, double fps) {
    return static_cast<std::uint64_t>(std::floor(durationSeconds * fps + 1e-9)) + 1;
}

// ---- records ----------------------------------------------------------------------------------

fs::path recordPath(const fs::path& dir, const std::string& unit) { return dir / kUnitFolder / (unit + ".json"); }

std::optional<json> readJson(const fs::path& file) {
    if (!fs::exists(file)) return std::nullopt;
    const JsonSource source = readJsonFile(file);
    return source.root;
}

// The digest of a frame folder: its files' names and digests, one per line.
std::string folderDigest(const fs::path& folder, std::uint64_t* files = nullptr) {
    Sha256 hash;
    std::vector<fs::path> names;
    for (const fs::directory_entry& e : fs::directory_iterator(folder)) names.push_back(e.path());
    std::sort(names.begin(), names.end());
    for (const fs::path& f : names) hash.update(f.filename().string() + " " + sha256File(f) + "\n");
    if (files) *files = names.size();
    return hash.hexDigest();
}

std::uint64_t folderBytes(const fs::path& folder) {
    std::uint64_t bytes = 0;
    for (const fs::directory_entry& e : fs::directory_iterator(folder)) bytes += e.file_size();
    return bytes;
}

// A unit is complete when its record has the current input hash and its files are there with
// the sizes recorded (verify checks the digests).
bool unitComplete(const fs::path& dir, const std::string& unit, const std::string& inputHash) {
    const std::optional<json> record = readJson(recordPath(dir, unit));
    if (!record || !record->is_object() || record->value("inputHash", "") != inputHash) return false;
    if (!record->contains("files") || !(*record)["files"].is_array()) return false;
    for (const json& f : (*record)["files"]) {
        const fs::path path = dir / f.value("path", "");
        if (f.value("kind", "") == "frames") {
            if (!fs::is_directory(path) || folderBytes(path) != f.value("bytes", std::uint64_t{0})) return false;
        } else if (!fs::is_regular_file(path) || fs::file_size(path) != f.value("bytes", std::uint64_t{0})) {
            return false;
        }
    }
    return true;
}

json fileEntry(const fs::path& dir, const std::string& relative, const std::string& kind) {
    const fs::path path = dir / relative;
    json entry;
    entry["path"] = relative;
    entry["kind"] = kind;
    if (kind == "frames") {
        std::uint64_t files = 0;
        entry["sha256"] = folderDigest(path, &files);
        entry["bytes"] = folderBytes(path);
        entry["files"] = files;
    } else {
        entry["sha256"] = sha256File(path);
        entry["bytes"] = static_cast<std::uint64_t>(fs::file_size(path));
    }
    return entry;
}

// ---- sinks ----------------------------------------------------------------------------------

// The sinks of one clip: MP4, optional PNG frames, the poster captured on the way.
struct ClipSinks {
    std::unique_ptr<render::FrameSink> video, frames;
    std::unique_ptr<render::TeeSink> tee;  // the MP4 and, when asked, the PNG frames
    std::unique_ptr<render::StillCapturingSink> still;
    bool finished = false;
    render::FrameSink* entry() { return still.get(); }
    void finish() {
        if (finished) return;
        finished = true;
        still->finish();
    }
};

std::unique_ptr<ClipSinks> makeClipSinks(const fs::path& dir, const ListedClip& clip, const render::FrameRate& rate,
                                         std::uint64_t posterFrame) {
    auto sinks = std::make_unique<ClipSinks>();
    render::VideoOptions video;
    video.frameRate = rate;
    video.threads = 1;  // identical bytes on every machine; parallelism is one encoder per clip
    video.niceness = 5;
    sinks->video = render::makeVideoSink(dir / clip.video, video, 8);
    render::FrameSink* next = sinks->video.get();
    if (!clip.frames.empty()) {
        sinks->frames = render::makePngSequenceSink(dir / clip.frames, {}, 1);
        sinks->tee = std::make_unique<render::TeeSink>(*sinks->video, *sinks->frames);
        next = sinks->tee.get();
    }
    sinks->still = std::make_unique<render::StillCapturingSink>(*next, posterFrame);
    return sinks;
}

// Where a clip's poster is taken: the middle of its first verb (where the versions differ).
double posterSeconds(const Timeline& timeline) {
    for (const TimelineSpan& span : timeline.spans)
        if (span.kind == SpanKind::Verb) return 0.5 * (span.startSeconds + span.endSeconds);
    return 0.5 * timeline.durationSeconds;
}

// ---- progress ---------------------------------------------------------------------------------

class Progress {
public:
    Progress(double totalWork, bool quiet)
        : total_(std::max(1.0, totalWork)), quiet_(quiet), terminal_(::isatty(STDERR_FILENO) == 1),
          start_(Clock::now()), last_(start_) {}

    void frames(double done, const std::string& unit, std::size_t unitNumber, std::size_t units) {
        done_ = done;
        if (quiet_) return;
        const auto now = Clock::now();
        if (now - last_ < std::chrono::milliseconds(terminal_ ? 250 : 10000)) return;
        last_ = now;
        print(unit, unitNumber, units, false);
    }
    void unitDone(double done, const std::string& unit, std::size_t unitNumber, std::size_t units) {
        done_ = done;
        if (quiet_) return;
        print(unit, unitNumber, units, !terminal_);
    }
    void end() {
        if (!quiet_ && terminal_ && printed_) std::fputc('\n', stderr);
    }

private:
    void print(const std::string& unit, std::size_t unitNumber, std::size_t units, bool unitLine) {
        const double elapsed = secondsSince(start_);
        const double fraction = std::min(1.0, done_ / total_);
        std::string eta = "estimating";
        if (done_ > 0.0 && elapsed > 1.0) {
            const double left = elapsed / fraction - elapsed;
            char text[32];
            std::snprintf(text, sizeof text, "%d:%02d left", static_cast<int>(left) / 60, static_cast<int>(left) % 60);
            eta = text;
        }
        if (terminal_) {
            const int width = 24;
            const int filled = static_cast<int>(fraction * width);
            std::string bar(static_cast<std::size_t>(filled), '#');
            bar.resize(width, '.');
            std::fprintf(stderr, "\rsignstim study [%s] %3.0f%%  %s (%zu/%zu)  %s   ", bar.c_str(), 100.0 * fraction,
                         unit.c_str(), unitNumber, units, eta.c_str());
            printed_ = true;
        } else {
            std::fprintf(stderr, "signstim study: %.0f%% %s (%zu/%zu)%s, %s\n", 100.0 * fraction, unit.c_str(), unitNumber,
                         units, unitLine ? " done" : "", eta.c_str());
        }
    }

    double total_, done_ = 0.0;  // work: estimated images drawn
    bool quiet_, terminal_;
    Clock::time_point start_, last_;
    bool printed_ = false;
};

// ---- rendering --------------------------------------------------------------------------------

// Renders the units of one run: one renderer (the device), encoders running beside it. A
// unit's encoders are finished, its posters written and its record committed on a worker
// while the renderer goes on with the next unit, as long as no more than `limit` encoders run.
class UnitRenderer {
public:
    UnitRenderer(const LoadedStudy& s, const StudyRunOptions& options, const fs::path& dir)
        : s_(s), options_(options), dir_(dir),
          signer_(s.world->scenes),
          renderer_(signer::signerRendererOptions(s.settings.width, s.settings.height, s.settings.msaa, options.device)) {
        handle_ = renderer_.addScene(signer_.avatar());
        const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
        // A story's versions are encoded together (its shared frames go to all of them at
        // once); the naive baseline finishes each clip before the next.
        limit_ = options.shareFrames ? std::max<std::size_t>(options.jobs > 0 ? options.jobs : cores, s.study.versions.size())
                                     : 1;
    }

    ~UnitRenderer() {
        // On an error the workers still hold sinks that reference nothing of ours; let them end.
        for (Pending& p : pending_)
            if (p.done.valid()) p.done.wait();
    }

    void render(const Unit& unit, const std::vector<Timeline>& timelines, const std::string& inputHash,
                const std::function<void(double)>& progress, StudyRunReport& report) {
        std::vector<std::unique_ptr<signer::TimelineClip>> clips;
        for (const Timeline& t : timelines)
            clips.push_back(std::make_unique<signer::TimelineClip>(signer_.rig(), t));
        std::vector<const signer::Clip*> clipPointers;
        for (const auto& c : clips) clipPointers.push_back(c.get());
        const double fps = s_.frameRate.value();
        const std::uint64_t poster = static_cast<std::uint64_t>(posterSeconds(timelines.front()) * fps);

        auto job = std::make_shared<Job>();
        job->unit = unit;
        job->inputHash = inputHash;
        std::vector<render::FrameSink*> entries;
        if (unit.story) {
            const ListedStory& story = s_.listing.stories[unit.index];
            for (std::size_t v = 0; v < story.clips.size(); ++v) {
                const ListedClip& clip = story.clips[v];
                job->clips.push_back(clip);
                job->shows.push_back({{"phase", 1}, {"story", story.id}, {"title", story.title},
                                      {"version", s_.listing.versions[v]}});
                job->sinks.push_back(makeClipSinks(dir_, clip, s_.frameRate, poster));
                entries.push_back(job->sinks.back()->entry());
            }
        } else {
            const ListedSentence& sentence = s_.listing.sentences[unit.index];
            json panels = json::object();
            for (std::size_t k = 0; k < sentence.panelVersion.size(); ++k)
                panels[panelLabel(k)] = s_.listing.versions[sentence.panelVersion[k]];
            job->clips.push_back(sentence.clip);
            job->shows.push_back({{"phase", 2}, {"sentence", sentence.id}, {"gloss", sentence.gloss}, {"verb", sentence.verb},
                                  {"panels", panels}});
            job->sinks.push_back(makeClipSinks(dir_, job->clips.back(), s_.frameRate, poster));
        }
        waitForEncoders(job->sinks.size(), report);

        const auto start = Clock::now();
        if (unit.story) {
            const auto frameProgress = [&](std::uint64_t done, std::uint64_t total) {
                progress(static_cast<double>(done) / static_cast<double>(total));
            };
            if (options_.shareFrames) {
                const signer::SharedRenderStats stats = signer::renderClipsSharingFrames(
                    renderer_, handle_, signer_.avatar(), signer_.rig(), clipPointers, fps, entries, frameProgress);
                report.renderedImages += stats.renderedImages;
                report.sharedFrames += stats.sharedFrames;
                report.clipFrames += stats.frames * clips.size();
                job->frames = stats.frames;
            } else {
                // The naive cost: each version drawn in full, one after the other.
                std::uint64_t before = 0;
                for (std::size_t i = 0; i < clips.size(); ++i) {
                    signer::ClipRenderOptions ro;
                    ro.framesPerSecond = fps;
                    const std::uint64_t n = signer::renderClips(
                        renderer_, handle_, signer_.avatar(), signer_.rig(), {clipPointers[i]}, {}, ro, *entries[i],
                        [&](std::uint64_t done, std::uint64_t total) {
                            progress(static_cast<double>(before + done) / static_cast<double>(total * clips.size()));
                        });
                    job->sinks[i]->finish();  // one clip after another, as separate runs would
                    before += n;
                    report.renderedImages += n;
                    report.clipFrames += n;
                    job->frames = n;
                }
            }
        } else {
            // Phase 2: the versions side by side, panel k showing panelVersion[k], labelled A, B, ...
            const ListedSentence& sentence = s_.listing.sentences[unit.index];
            std::vector<const signer::Clip*> panels;
            std::vector<std::string> labels;
            for (std::size_t k = 0; k < sentence.panelVersion.size(); ++k) {
                panels.push_back(clipPointers[sentence.panelVersion[k]]);
                labels.push_back(panelLabel(k));
            }
            signer::ClipRenderOptions ro;
            ro.framesPerSecond = fps;
            ro.columns = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(panels.size()))));
            ro.rows = static_cast<std::uint32_t>((panels.size() + ro.columns - 1) / ro.columns);
            const std::uint64_t n =
                signer::renderClips(renderer_, handle_, signer_.avatar(), signer_.rig(), panels, labels, ro,
                                    *job->sinks.front()->entry(), [&](std::uint64_t done, std::uint64_t total) {
                                        progress(static_cast<double>(done) / static_cast<double>(total));
                                    });
            report.renderedImages += n;
            report.clipFrames += n;
            job->frames = n;
        }
        report.renderSeconds += secondsSince(start);
        failOnValidationMessages(renderer_);

        // Finish on a worker: encoders drain while the next unit renders.
        const fs::path dir = dir_;
        const render::FrameRate rate = s_.frameRate;
        const StudyRenderSettings settings = s_.settings;
        Pending pending;
        pending.encoders = job->sinks.size();
        pending.done = std::async(std::launch::async, [job, dir, rate, settings] { finishUnit(*job, dir, rate, settings); });
        pending_.push_back(std::move(pending));
    }

    void finishAll(StudyRunReport& report) {
        const auto start = Clock::now();
        while (!pending_.empty()) {
            pending_.front().done.get();
            pending_.pop_front();
        }
        report.encodeWaitSeconds += secondsSince(start);
    }

private:
    struct Job {
        Unit unit;
        std::string inputHash;
        std::vector<ListedClip> clips;
        std::vector<json> shows;  // what each clip shows, for the manifest
        std::vector<std::unique_ptr<ClipSinks>> sinks;
        std::uint64_t frames = 0;
    };
    struct Pending {
        std::size_t encoders = 0;
        std::future<void> done;
    };

    void waitForEncoders(std::size_t needed, StudyRunReport& report) {
        const auto start = Clock::now();
        auto running = [&] {
            std::size_t n = 0;
            for (const Pending& p : pending_) n += p.encoders;
            return n;
        };
        while (!pending_.empty() && running() + needed > limit_) {
            pending_.front().done.get();
            pending_.pop_front();
        }
        report.encodeWaitSeconds += secondsSince(start);
    }

    static void finishUnit(Job& job, const fs::path& dir, const render::FrameRate& rate, const StudyRenderSettings& settings) {
        json files = json::array();
        for (std::size_t i = 0; i < job.sinks.size(); ++i) {
            ClipSinks& sinks = *job.sinks[i];
            sinks.finish();
            const ListedClip& clip = job.clips[i];
            render::writeImage(sinks.still->still(), dir / clip.poster);
            json video = fileEntry(dir, clip.video, "video");
            video["frames"] = job.frames;
            video["fps"] = rate.text();
            video["width"] = settings.width;
            video["height"] = settings.height;
            video["durationSeconds"] = static_cast<double>(job.frames) / rate.value();
            video["shows"] = job.shows[i];
            files.push_back(video);
            json poster = fileEntry(dir, clip.poster, "poster");
            poster["width"] = settings.width;
            poster["height"] = settings.height;
            poster["shows"] = job.shows[i];
            files.push_back(poster);
            if (!clip.frames.empty()) {
                json frames = fileEntry(dir, clip.frames, "frames");
                frames["shows"] = job.shows[i];
                files.push_back(frames);
            }
        }
        json record;
        record["unit"] = job.unit.id;
        record["inputHash"] = job.inputHash;
        record["frames"] = job.frames;
        record["files"] = files;
        writeFileAtomic(recordPath(dir, job.unit.id), record.dump(2) + "\n");
    }

    const LoadedStudy& s_;
    const StudyRunOptions& options_;
    fs::path dir_;
    signer::Signer signer_;
    render::Renderer renderer_;
    int handle_ = 0;
    std::size_t limit_ = 4;
    std::deque<Pending> pending_;
};

// ---- finishing: durations, documents, manifest ---------------------------------------------------

// The listing with every clip's frame count and duration from the unit records; the units
// that have no valid record are returned in `missing`.
StudyListing completedListing(const fs::path& dir, StudyListing listing, const std::map<std::string, std::string>& inputHashes,
                              std::vector<std::string>& missing, std::vector<json>& records) {
    std::map<std::string, json> videos;  // path -> entry
    for (const auto& [unit, hash] : inputHashes) {
        if (!unitComplete(dir, unit, hash)) {
            missing.push_back(unit);
            continue;
        }
        json record = *readJson(recordPath(dir, unit));
        for (const json& f : record["files"])
            if (f.value("kind", "") == "video") videos[f.value("path", "")] = f;
        records.push_back(std::move(record));
    }
    const auto fill = [&](ListedClip& clip) {
        const auto it = videos.find(clip.video);
        if (it == videos.end()) return;
        clip.frameCount = it->second.value("frames", std::uint64_t{0});
        clip.durationSeconds = it->second.value("durationSeconds", 0.0);
    };
    for (ListedStory& story : listing.stories)
        for (ListedClip& clip : story.clips) fill(clip);
    for (ListedSentence& sentence : listing.sentences) fill(sentence.clip);
    return listing;
}

std::map<std::string, std::string> planHashes(const json& plan) {
    std::map<std::string, std::string> hashes;
    for (const json& u : plan.at("units")) hashes[u.at("id").get<std::string>()] = u.at("inputHash").get<std::string>();
    return hashes;
}

void writeFinalFiles(const fs::path& dir, const json& plan, const StudyListing& listing, const std::vector<json>& records,
                     const JspsychBundle* jspsych, StudyRunReport& report) {
    const auto start = Clock::now();
    json files = json::array();
    for (const json& record : records)
        for (const json& f : record["files"]) files.push_back(f);
    std::vector<StudyDocument> documents = studyDocuments(listing);
    if (jspsych) {
        std::vector<StudyDocument> experiment = experimentDocuments(listing, *jspsych);
        documents.insert(documents.end(), std::make_move_iterator(experiment.begin()),
                         std::make_move_iterator(experiment.end()));
        report.experiment = true;
        if (!listing.participants.empty()) report.firstParticipant = listing.participants.front().id;
    }
    for (const StudyDocument& document : documents) {
        writeFileAtomic(dir / document.path, document.contents);
        json entry;
        entry["path"] = document.path;
        entry["kind"] = document.kind;
        entry["sha256"] = sha256Hex(document.contents);
        entry["bytes"] = static_cast<std::uint64_t>(document.contents.size());
        if (!document.participant.empty()) entry["participant"] = document.participant;
        entry["shows"] = document.shows;
        files.push_back(entry);
    }
    std::sort(files.begin(), files.end(), [](const json& a, const json& b) { return a["path"] < b["path"]; });
    json units = json::array();
    for (const json& record : records)
        units.push_back({{"id", record["unit"]}, {"inputHash", record["inputHash"]}, {"frames", record["frames"]}});
    json manifest;
    manifest["format"] = "signstim-study-manifest";
    manifest["version"] = 1;
    manifest["tool"] = std::string("signstim ") + listing.toolVersion;
    manifest["title"] = listing.title;
    manifest["seed"] = listing.seed;
    manifest["designHash"] = listing.designHash;
    manifest["render"] = plan.at("render");
    manifest["units"] = units;
    manifest["files"] = files;
    manifest["study"] = listingToJson(listing);
    writeFileAtomic(dir / kManifestFile, manifest.dump(2) + "\n");
    report.writeSeconds += secondsSince(start);
}

json makePlan(const LoadedStudy& s) {
    json plan;
    plan["format"] = "signstim-study-plan";
    plan["version"] = 1;
    plan["render"] = {{"size", s.listing.size}, {"fps", s.listing.fps}, {"msaa", s.settings.msaa},
                      {"rate", s.settings.rate}, {"pngFrames", s.pngFrames}};
    json units = json::array();
    for (const Unit& u : s.units) units.push_back({{"id", u.id}, {"inputHash", unitInputHash(s, u)}});
    plan["units"] = units;
    plan["listing"] = listingToJson(s.listing);
    // Not part of what a unit depends on: a re-run with another choice only rewrites the documents.
    if (!s.experiment.empty()) plan["outputs"] = {{"experiment", s.experiment}};
    return plan;
}

// "jspsych" when the run that wrote `plan` asked for the experiment, else empty.
std::string planExperiment(const json& plan) {
    if (!plan.contains("outputs") || !plan["outputs"].is_object()) return "";
    return plan["outputs"].value("experiment", "");
}

json readPlan(const fs::path& dir) {
    const fs::path file = dir / kPlanFile;
    if (!fs::exists(file))
        throw InputError(file.string(), 0, "", "not a study folder (no plan): run `signstim study ... --out " + dir.string() + "` first");
    const JsonSource source = readJsonFile(file);
    source.checkFormat("signstim-study-plan", 1);
    if (!source.root.contains("units") || !source.root.contains("listing") || !source.root.contains("render"))
        source.failAt("", "incomplete plan (units, listing, render)");
    return source.root;
}

// Writes the documents and manifest when every unit is complete (and the experiment with them
// when `jspsych` is given).
void finishIfComplete(const fs::path& dir, const json& plan, const JspsychBundle* jspsych, StudyRunReport& report) {
    std::vector<json> records;
    const StudyListing listing = completedListing(dir, listingFromJson(plan.at("listing"), (dir / kPlanFile).string()),
                                                  planHashes(plan), report.missing, records);
    report.units = planHashes(plan).size();
    report.complete = report.missing.empty();
    if (report.complete) writeFinalFiles(dir, plan, listing, records, jspsych, report);
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
    const char* id = std::getenv("SLURM_ARRAY_TASK_ID");
    const char* count = std::getenv("SLURM_ARRAY_TASK_COUNT");
    if (!id || !count) return {0, 1};
    const char* minimum = std::getenv("SLURM_ARRAY_TASK_MIN");
    const long long first = minimum ? std::atoll(minimum) : 0;
    const long long task = std::atoll(id), tasks = std::atoll(count);
    if (tasks <= 0 || task - first < 0 || task - first >= tasks)
        throw InputError("<environment>", 0, "SLURM_ARRAY_TASK_ID",
                         std::string("task ") + id + " of " + count + " (min " + (minimum ? minimum : "0") +
                             ") is not a shard; give --shard I/N");
    return {static_cast<std::size_t>(task - first), static_cast<std::size_t>(tasks)};
}

void checkStudy(const StudyRunOptions& options) {
    LoadedStudy s = loadStudy(options);
    useExperiment(s, "");
    double storySeconds = 0.0, likertSeconds = 0.0;
    for (const Unit& unit : s.units) {
        const Story story = unitStory(s, unit);
        const std::vector<Timeline> timelines = unitTimelines(s, story);
        (unit.story ? storySeconds : likertSeconds) += timelines.front().durationSeconds;
    }
    const StudyDesignSpec spec = s.study.designSpec();
    std::printf("%s: ok: \"%s\"\n  %zu stories x %zu versions, %zu participants in %zu groups (each sees every story once, "
                "each version %zu time%s), %zu side-by-side sentences\n  %.0f s of stories per version, %.0f s of side-by-side "
                "clips; design %s\n",
                s.study.file.c_str(), s.study.title.c_str(), spec.stories, spec.versions, spec.participants, spec.versions,
                spec.stories / spec.versions, spec.stories / spec.versions == 1 ? "" : "s", spec.likertTrials, storySeconds, likertSeconds,
                s.listing.designHash.substr(0, 12).c_str());
}

StudyRunReport runStudy(const StudyRunOptions& options) {
    const auto start = Clock::now();
    StudyRunReport report;
    LoadedStudy s = loadStudy(options);
    const fs::path& dir = options.out;
    const std::optional<json> old = fs::exists(dir / kPlanFile) ? std::optional<json>(readPlan(dir)) : std::nullopt;
    useExperiment(s, old ? planExperiment(*old) : "");
    // Found and read before the first frame: a missing jsPsych fails now, not after the clips.
    const std::optional<JspsychBundle> jspsych =
        s.experiment.empty() ? std::nullopt : std::optional<JspsychBundle>(loadJspsychBundle());
    ensureWritableDirectory(dir);
    // What a run killed outright (SIGKILL, a node lost) left behind on this machine.
    if (const std::size_t stale = removeStaleTemporaries(dir); stale > 0 && !options.quiet)
        std::fprintf(stderr, "signstim study: removed %zu temporar%s left by a killed run\n", stale, stale == 1 ? "y" : "ies");
    const json plan = makePlan(s);
    if (old) {
        // A folder of another study is not overwritten unit by unit: that would mix two studies.
        if (old->at("listing").value("designHash", "") != s.listing.designHash)
            throw InputError(dir.string(), 0, "--out",
                             "holds another study (design " + old->at("listing").value("designHash", "").substr(0, 12) +
                                 ", this one " + s.listing.designHash.substr(0, 12) + "): choose a new folder");
    }
    writeFileAtomic(dir / kPlanFile, plan.dump(2) + "\n");

    const std::map<std::string, std::string> hashes = planHashes(plan);
    std::vector<Unit> mine;
    for (std::size_t i = 0; i < s.units.size(); ++i)
        if (i % options.shardCount == options.shardIndex) mine.push_back(s.units[i]);
    report.units = s.units.size();
    report.unitsInShard = mine.size();

    // Timelines first (cheap): the frame count for the progress bar, and every verb checked
    // before the first frame.
    const auto timelineStart = Clock::now();
    struct Work {
        Unit unit;
        std::vector<Timeline> timelines;
        double weight = 0.0;  // estimated images to draw: what the progress bar counts
    };
    std::vector<Work> work;
    double totalWeight = 0.0;
    for (const Unit& unit : mine) {
        if (unitComplete(dir, unit.id, hashes.at(unit.id))) {
            ++report.skipped;
            continue;
        }
        Work w{unit, unitTimelines(s, unitStory(s, unit)), 0};
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
        UnitRenderer renderer(s, options, dir);
        Progress progress(totalWeight, options.quiet);
        double before = 0.0;
        for (std::size_t i = 0; i < work.size(); ++i) {
            const Work& w = work[i];
            renderer.render(
                w.unit, w.timelines, hashes.at(w.unit.id),
                [&](double fraction) { progress.frames(before + fraction * w.weight, w.unit.id, i + 1, work.size()); },
                report);
            before += w.weight;
            progress.unitDone(before, w.unit.id, i + 1, work.size());
            ++report.rendered;
        }
        renderer.finishAll(report);
        progress.end();
    }
    finishIfComplete(dir, plan, jspsych ? &*jspsych : nullptr, report);
    report.totalSeconds = secondsSince(start);
    return report;
}

std::vector<std::string> verifyStudyFolder(const fs::path& dir, bool quiet) {
    const fs::path manifestFile = dir / kManifestFile;
    if (!fs::exists(manifestFile)) {
        std::string why = "no manifest: the study is not complete";
        if (fs::exists(dir / kPlanFile)) {
            const json plan = readPlan(dir);
            std::vector<std::string> missing;
            for (const auto& [unit, hash] : planHashes(plan))
                if (!unitComplete(dir, unit, hash)) missing.push_back(unit);
            if (!missing.empty()) {
                why += " (" + std::to_string(missing.size()) + " unit" + (missing.size() == 1 ? "" : "s") + " missing: ";
                for (std::size_t i = 0; i < missing.size() && i < 8; ++i) why += (i ? ", " : "") + missing[i];
                why += missing.size() > 8 ? ", ...)" : ")";
            }
        }
        throw InputError(manifestFile.string(), 0, "", why);
    }
    const JsonSource source = readJsonFile(manifestFile);
    source.checkFormat("signstim-study-manifest", 1);
    if (!source.root.contains("files") || !source.root["files"].is_array()) source.failAt("/files", "expected the list of files");
    std::vector<std::string> problems;
    std::size_t checked = 0;
    for (const json& f : source.root["files"]) {
        const std::string relative = f.value("path", "");
        const fs::path path = dir / relative;
        const std::string kind = f.value("kind", "");
        if (relative.empty() || fs::path(relative).is_absolute() || relative.find("..") != std::string::npos) {
            problems.push_back("manifest lists a path outside the folder: '" + relative + "'");
            continue;
        }
        if (kind == "frames" ? !fs::is_directory(path) : !fs::is_regular_file(path)) {
            problems.push_back(relative + ": missing");
            continue;
        }
        const std::uint64_t bytes = kind == "frames" ? folderBytes(path) : fs::file_size(path);
        if (bytes != f.value("bytes", std::uint64_t{0})) {
            problems.push_back(relative + ": " + std::to_string(bytes) + " bytes, the manifest says " +
                               std::to_string(f.value("bytes", std::uint64_t{0})));
            continue;
        }
        const std::string digest = kind == "frames" ? folderDigest(path) : sha256File(path);
        if (digest != f.value("sha256", "")) problems.push_back(relative + ": SHA-256 differs from the manifest's");
        ++checked;
    }
    // Every unit of the plan must be in the manifest.
    if (fs::exists(dir / kPlanFile)) {
        std::set<std::string> listed;
        for (const json& u : source.root.value("units", json::array())) listed.insert(u.value("id", ""));
        for (const auto& [unit, hash] : planHashes(readPlan(dir)))
            if (!listed.count(unit)) problems.push_back(unit + ": in the plan but not in the manifest");
    }
    if (!quiet)
        std::fprintf(stderr, "signstim study verify: %zu of %zu files match the manifest\n", checked,
                     source.root["files"].size());
    return problems;
}

StudyRunReport mergeStudyFolders(const std::vector<fs::path>& sources, const fs::path& target, bool quiet,
                                 const std::string& experiment) {
    StudyRunReport report;
    const auto start = Clock::now();
    // The plan: the target's, else the first source's; every source must hold the same study.
    std::optional<json> plan;
    fs::path planFrom;
    // Shards of one study may differ in whether they asked for the experiment; the merge writes
    // it when any of them (or `experiment`) did.
    std::string wantedExperiment = experiment == "none" ? "" : experiment;
    const auto withoutOutputs = [](json p) {
        p.erase("outputs");
        return p;
    };
    for (const fs::path& dir : [&] {
             std::vector<fs::path> all{target};
             all.insert(all.end(), sources.begin(), sources.end());
             return all;
         }()) {
        if (!fs::exists(dir / kPlanFile)) continue;
        const json p = readPlan(dir);
        if (wantedExperiment.empty()) wantedExperiment = planExperiment(p);
        if (!plan) {
            plan = p;
            planFrom = dir;
        } else if (withoutOutputs(p) != withoutOutputs(*plan)) {
            throw InputError(dir.string(), 0, "",
                             "holds a different study (or the same with other settings) than " + planFrom.string() +
                                 ": merge the shards of one run of one study file");
        }
    }
    if (!plan) throw InputError(sources.front().string(), 0, "", "not a study folder (no .signstim/plan.json)");
    plan->erase("outputs");
    if (!wantedExperiment.empty()) (*plan)["outputs"] = {{"experiment", wantedExperiment}};
    const std::optional<JspsychBundle> jspsych =
        wantedExperiment.empty() ? std::nullopt : std::optional<JspsychBundle>(loadJspsychBundle());
    ensureWritableDirectory(target);
    removeStaleTemporaries(target);
    writeFileAtomic(target / kPlanFile, plan->dump(2) + "\n");
    const std::map<std::string, std::string> hashes = planHashes(*plan);
    std::size_t copied = 0;
    for (const auto& [unit, hash] : hashes) {
        if (unitComplete(target, unit, hash)) continue;
        for (const fs::path& dir : sources) {
            if (fs::equivalent(dir, target) || !unitComplete(dir, unit, hash)) continue;
            const json record = *readJson(recordPath(dir, unit));
            for (const json& f : record["files"]) {
                const std::string relative = f.value("path", "");
                const fs::path from = dir / relative, to = target / relative;
                if (f.value("kind", "") == "frames") {
                    if (folderDigest(from) != f.value("sha256", ""))
                        throw InputError(from.string(), 0, "", "its frames differ from the unit's record (changed after rendering?)");
                    TemporaryFolder folder(to);
                    for (const fs::directory_entry& e : fs::directory_iterator(from))
                        writeNewFile(folder.path() / e.path().filename(), readTextFile(e.path()), to / e.path().filename());
                    folder.commit();
                } else {
                    const std::string bytes = readTextFile(from);
                    if (sha256Hex(bytes) != f.value("sha256", ""))
                        throw InputError(from.string(), 0, "", "differs from the unit's record (changed after rendering?)");
                    writeFileAtomic(to, bytes);
                }
            }
            writeFileAtomic(recordPath(target, unit), record.dump(2) + "\n");
            ++copied;
            break;
        }
    }
    finishIfComplete(target, *plan, jspsych ? &*jspsych : nullptr, report);
    report.rendered = copied;
    report.totalSeconds = secondsSince(start);
    if (!quiet) std::fprintf(stderr, "signstim study merge: %zu unit%s copied into %s\n", copied, copied == 1 ? "" : "s",
                             target.string().c_str());
    return report;
}

}  // namespace signstim::app
