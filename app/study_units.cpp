#include "app/study_units.hpp"

#include "app/clip_output.hpp"
#include "app/study_annotations.hpp"
#include "common/atomic_file.hpp"
#include "common/file_manifest.hpp"
#include "renderer/frame_sink.hpp"
#include "renderer/image_io.hpp"
#include "renderer/relay_sinks.hpp"
#include "renderer/renderer.hpp"
#include "signer/avatar_render.hpp"
#include "signer/timeline_clip.hpp"
#include "signer/clip_render.hpp"
#include "signer/signer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <future>
#include <thread>

namespace signstim::app {

using namespace signstim::stimuli;
using nlohmann::json;
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// ---- sinks ----------------------------------------------------------------------------------

// The sinks of one clip: MP4, optional PNG frames, the poster captured on the way.
struct ClipSinks {
    std::unique_ptr<render::FrameSink> video, frames;
    std::unique_ptr<render::TeeSink> tee;  // the MP4 and, when asked, the PNG frames
    std::unique_ptr<render::StillCapturingSink> still;
    // Human-video panels drawn over a side-by-side clip (app/study_human.hpp), each wrapping the last.
    std::vector<std::unique_ptr<render::VideoCellSink>> cells;
    bool finished = false;
    render::FrameSink* entry() { return cells.empty() ? static_cast<render::FrameSink*>(still.get()) : cells.back().get(); }
    void finish() {
        if (finished) return;
        finished = true;
        entry()->finish();  // a video cell finishes the ones inside it, down to the still
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


}  // namespace

// ---- rendering --------------------------------------------------------------------------------

// Renders the units of one run: one renderer (the device), encoders running beside it. A
// unit's encoders are finished, its posters written and its record committed on a worker
// while the renderer goes on with the next unit, as long as no more than `limit` encoders run.
struct UnitRenderer::State {
    State(const LoadedStudy& s, const StudyRunOptions& options, const fs::path& dir)
        : s_(s), options_(options), dir_(dir),
          signer_(s.world->scenes),
          renderer_(signer::signerRendererOptions(s.settings.width, s.settings.height, s.settings.msaa, options.device)),
          regionModel_(signer_.avatar(), signer_.rig()) {
        handle_ = renderer_.addScene(signer_.avatar());
        const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
        // A story's versions are encoded together (its shared frames go to all of them at
        // once); the naive baseline finishes each clip before the next.
        limit_ = options.shareFrames ? std::max<std::size_t>(options.jobs > 0 ? options.jobs : cores, s.listing.versions.size())
                                     : 1;
    }

    ~State() {
        // On an error the workers still hold sinks that reference nothing of ours; let them end.
        for (Pending& p : pending_)
            if (p.done.valid()) p.done.wait();
    }

    struct Job;  // below

    void render(const StudyUnit& unit, const std::vector<Timeline>& timelines, const std::string& inputHash,
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
        if (unit.kind != StudyUnitKind::Stimulus) {
            renderSignedText(job, clipPointers, timelines, progress, report);
            return;
        }
        std::vector<render::FrameSink*> entries;
        // The lab's recordings this unit shows (human-video versions), in version / panel order.
        const auto humanEntry = s_.humanClips.find(unit.id);
        const std::vector<HumanClip> noHuman;
        const std::vector<HumanClip>& human = humanEntry == s_.humanClips.end() ? noHuman : humanEntry->second;
        if (unit.story) {
            const ListedStory& story = s_.listing.stories[unit.index];
            for (std::size_t v = 0; v < story.clips.size(); ++v) {
                const ListedClip& clip = story.clips[v];
                job->clips.push_back(clip);
                job->shows.push_back({{"phase", 1}, {"story", story.id}, {"title", story.title},
                                      {"version", s_.listing.versions[v]}});
                const bool animated = v < clips.size();  // the human versions come after the animated ones
                const HumanClip* recording = nullptr;
                for (const HumanClip& h : human)
                    if (h.version == v) recording = &h;
                if (recording) job->shows.back()["source"] = humanSource(*recording);
                job->sinks.push_back(makeClipSinks(
                    dir_, clip, s_.frameRate, animated || !recording ? poster : humanPosterFrame(*recording, s_.frameRate)));
                if (animated) entries.push_back(job->sinks.back()->entry());
            }
        } else {
            const ListedSentence& sentence = s_.listing.sentences[unit.index];
            json panels = json::object();
            for (std::size_t k = 0; k < sentence.panelVersion.size(); ++k)
                panels[panelLabel(k)] = s_.listing.versions[sentence.panelVersion[k]];
            job->clips.push_back(sentence.clip);
            job->shows.push_back({{"phase", 2}, {"sentence", sentence.id}, {"gloss", sentence.gloss}, {"verb", sentence.verb},
                                  {"panels", panels}});
            if (!human.empty()) {
                json sources = json::object();
                std::size_t next = 0;
                for (std::size_t k = 0; k < sentence.panelVersion.size(); ++k)
                    if (sentence.panelVersion[k] >= clips.size() && next < human.size())
                        sources[panelLabel(k)] = humanSource(human[next++]);
                job->shows.back()["sources"] = sources;
            }
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
            // The human versions: the lab's recordings, normalised to the study's size, rate and
            // format, through the same sinks (MP4, poster, PNG frames) as the animated ones.
            for (const HumanClip& h : human) {
                const auto reader = humanFrames(h, s_.settings.width, s_.settings.height, s_.frameRate);
                render::FrameSink& sink = *job->sinks.at(h.version)->entry();
                render::Image frame;
                while (reader->next(frame)) sink.push(std::move(frame));
                report.clipFrames += reader->framesRead();
            }
        } else {
            // Phase 2: the versions side by side, panel k showing panelVersion[k], labelled A, B, ...
            const ListedSentence& sentence = s_.listing.sentences[unit.index];
            std::vector<const signer::Clip*> panels;
            std::vector<std::string> labels;
            for (std::size_t k = 0; k < sentence.panelVersion.size(); ++k) {
                // A human version's panel is drawn over (below); the signer drawn there first is never seen.
                const std::size_t v = sentence.panelVersion[k];
                panels.push_back(clipPointers[v < clipPointers.size() ? v : 0]);
                labels.push_back(panelLabel(k));
            }
            signer::ClipRenderOptions ro;
            ro.framesPerSecond = fps;
            ro.columns = static_cast<std::uint32_t>(std::ceil(std::sqrt(static_cast<double>(panels.size()))));
            ro.rows = static_cast<std::uint32_t>((panels.size() + ro.columns - 1) / ro.columns);
            // The lab's recordings into their panels, letterboxed to the panel's size, labelled like the others.
            ClipSinks& sinks = *job->sinks.front();
            std::size_t next = 0;
            for (std::size_t k = 0; k < sentence.panelVersion.size(); ++k) {
                if (sentence.panelVersion[k] < clipPointers.size() || next >= human.size()) continue;
                const render::LabelRect cell = render::gridCell(s_.settings.width, s_.settings.height, ro.columns, ro.rows, k);
                render::FrameSink& inner = *sinks.entry();
                sinks.cells.push_back(std::make_unique<render::VideoCellSink>(
                    inner, humanFrames(human[next++], cell.width, cell.height, s_.frameRate), cell, panelLabel(k)));
            }
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
        // Eye-tracking regions and ELAN files beside the clips (app/study_annotations.hpp).
        const auto annotating = Clock::now();
        job->annotations = makeUnitAnnotations(s_, signer_, regionModel_, unit, timelines, clipPointers);
        report.annotationSeconds += secondsSince(annotating);

        // Finish on a worker: encoders drain while the next unit renders.
        const fs::path dir = dir_;
        const render::FrameRate rate = s_.frameRate;
        const StudyRenderSettings settings = s_.settings;
        Pending pending;
        pending.encoders = job->sinks.size();
        pending.done = std::async(std::launch::async, [job, dir, rate, settings] { finishUnit(*job, dir, rate, settings); });
        pending_.push_back(std::move(pending));
    }

    // Issue 24: a unit of signed questions or instructions: each clip drawn on its own, one after
    // the other (they are short and differ from every other clip), encoded as the stories are.
    void renderSignedText(const std::shared_ptr<Job>& job, const std::vector<const signer::Clip*>& clips,
                          const std::vector<Timeline>& timelines, const std::function<void(double)>& progress,
                          StudyRunReport& report) {
        const double fps = s_.frameRate.value();
        std::vector<json> shows;
        if (job->unit.kind == StudyUnitKind::Questions) {
            const ListedStory& story = s_.listing.stories[job->unit.index];
            for (std::size_t q = 0; q < story.questions.size(); ++q) {
                if (story.questions[q].clip.video.empty()) continue;
                job->clips.push_back(story.questions[q].clip);
                shows.push_back({{"question", q + 1}, {"story", story.id}, {"gloss", story.questions[q].gloss},
                                 {"text", story.questions[q].text}, {"verbVersion", "uninflected"}});
            }
        } else {
            for (const ListedInstruction& page : s_.listing.instructions) {
                if (page.clip.video.empty()) continue;
                job->clips.push_back(page.clip);
                shows.push_back({{"instructions", page.page}, {"gloss", page.gloss}});
            }
        }
        if (job->clips.size() != clips.size())
            throw std::logic_error("study unit " + job->unit.id + ": " + std::to_string(clips.size()) + " timelines for " +
                                   std::to_string(job->clips.size()) + " clips");
        job->shows = shows;
        for (std::size_t i = 0; i < clips.size(); ++i) {
            // The poster: the middle of the clip (a question has no verb slot to show).
            const auto poster = static_cast<std::uint64_t>(0.5 * timelines[i].durationSeconds * fps);
            job->sinks.push_back(makeClipSinks(dir_, job->clips[i], s_.frameRate, poster));
        }
        waitForEncoders(job->sinks.size(), report);
        const auto start = Clock::now();
        std::uint64_t total = 0, before = 0;
        for (const Timeline& t : timelines)
            total += static_cast<std::uint64_t>(std::floor(t.durationSeconds * fps + 1e-9)) + 1;
        for (std::size_t i = 0; i < clips.size(); ++i) {
            signer::ClipRenderOptions ro;
            ro.framesPerSecond = fps;
            const std::uint64_t n = signer::renderClips(
                renderer_, handle_, signer_.avatar(), signer_.rig(), {clips[i]}, {}, ro, *job->sinks[i]->entry(),
                [&](std::uint64_t done, std::uint64_t) {
                    progress(static_cast<double>(before + done) / static_cast<double>(std::max<std::uint64_t>(total, 1)));
                });
            before += n;
            job->frames += n;
            report.renderedImages += n;
            report.clipFrames += n;
        }
        report.renderSeconds += secondsSince(start);
        failOnValidationMessages(renderer_);
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

    struct Job {
        StudyUnit unit;
        std::string inputHash;
        std::vector<ListedClip> clips;
        std::vector<json> shows;  // what each clip shows, for the manifest
        std::vector<std::unique_ptr<ClipSinks>> sinks;
        std::uint64_t frames = 0;
        UnitAnnotations annotations;
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
            json video = describeFile(dir, clip.video, "video");
            // Each clip's own count: a human version's recording has its own length.
            const std::uint64_t frames = sinks.still->framesPushed();
            video["frames"] = frames;
            video["fps"] = rate.text();
            video["width"] = settings.width;
            video["height"] = settings.height;
            video["durationSeconds"] = static_cast<double>(frames) / rate.value();
            video["shows"] = job.shows[i];
            files.push_back(video);
            json poster = describeFile(dir, clip.poster, "poster");
            poster["width"] = settings.width;
            poster["height"] = settings.height;
            poster["shows"] = job.shows[i];
            files.push_back(poster);
            if (!clip.frames.empty()) {
                json frames = describeFile(dir, clip.frames, "frames");
                frames["shows"] = job.shows[i];
                files.push_back(frames);
            }
            writeUnitAnnotations(dir, clip, job.annotations, i, job.shows[i], files);
        }
        writeUnitRecord(dir, job.unit.id, job.inputHash, job.frames, files);
    }

    const LoadedStudy& s_;
    const StudyRunOptions& options_;
    fs::path dir_;
    signer::Signer signer_;
    render::Renderer renderer_;
    signer::ScreenRegionModel regionModel_;
    int handle_ = 0;
    std::size_t limit_ = 4;
    std::deque<Pending> pending_;
};


UnitRenderer::UnitRenderer(const LoadedStudy& s, const StudyRunOptions& options, const fs::path& dir)
    : state_(std::make_unique<State>(s, options, dir)) {}

UnitRenderer::~UnitRenderer() = default;

void UnitRenderer::render(const StudyUnit& unit, const std::vector<Timeline>& timelines, const std::string& inputHash,
                          const std::function<void(double)>& progress, StudyRunReport& report) {
    state_->render(unit, timelines, inputHash, progress, report);
}

void UnitRenderer::finishAll(StudyRunReport& report) { state_->finishAll(report); }

}  // namespace signstim::app
