// `signstim story`: a story file (docs/stories.md) checked, as a timeline, or rendered in one
// of the four versions.
#include "app/cli_values.hpp"
#include "app/clip_output.hpp"
#include "app/commands.hpp"
#include "app/story_timing.hpp"
#include "stimuli/story/story_world.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/standard_output.hpp"
#include "signer/clearance.hpp"
#include "signer/screen_regions.hpp"
#include "signer/signer.hpp"
#include "signer/signer_reach.hpp"
#include "signer/timeline_clip.hpp"
#include "stimuli/story/lexicon.hpp"
#include "stimuli/story/nonmanuals.hpp"
#include "stimuli/scenes_path.hpp"
#include "stimuli/story/story.hpp"
#include "stimuli/story/timeline_builder.hpp"
#include "stimuli/study/elan_export.hpp"
#include "stimuli/verbs/verb_models.hpp"

#include <cmath>
#include <filesystem>
#include <cstdio>
#include <memory>
#include <optional>

namespace signstim::app {

using namespace signstim::signer;
namespace fs = std::filesystem;

namespace {

using namespace signstim::stimuli;

struct StoryOptions {
    std::string file;
    std::string version;
    std::string outPath;
    bool check = false;
    bool json = false;
    std::string size = "640x480";
    std::string fps = "30";
    std::uint32_t msaa = 4;
    std::string camera = "waist-up";
    std::string device;
    double rate = 1.0;
    std::string timing;  // --timing: a preset replacing the story's `timing`
    bool strict = false;
    std::string scenesDir;
    std::string lexiconFile;
    bool quiet = false;
    bool annotations = false;  // --annotations: FILE.regions.csv and FILE.eaf beside FILE.mp4
};

VerbVersion requireVersion(const StoryOptions& o) {
    if (o.version.empty()) throw commandLineError("--version", "give the version: point, vector, animator or uninflected");
    const std::optional<VerbVersion> v = parseVerbVersion(o.version);
    if (!v) throw commandLineError("--version", "'" + o.version + "' is not a version (point, vector, animator, uninflected)");
    return *v;
}

// `--check`: how close the signer's hands come, to each other and to the body, in each
// version (signer/clearance.hpp), and where a rule is broken.
// The version's timeline, or (saying so) none when it is the animator version and its keyframe
// files are missing: --check reports the other versions and the list of missing files.
std::optional<Timeline> timelineUnlessFilesMissing(const StoryWorld& world, const Story& story, VerbVersion v,
                                                   const TimelineOptions& timing, const char* what) {
    try {
        return buildTimeline(story, v, world.sources(story), timing);
    } catch (const MissingAnimatorFiles&) {
        std::printf("  %s: not %s (keyframe files missing)\n", toString(v).c_str(), what);
        return std::nullopt;
    }
}

void reportClearance(const StoryWorld& world, const Story& story, const TimelineOptions& timing) {
    const Signer signer(world.scenes);
    const auto place = [](const Timeline& t, const ClearanceExtreme& e) {
        char text[200];
        std::snprintf(text, sizeof text, "%.1f mm (%s, %.2f s)", e.gapMm, describeClearancePlace(t, e.before, e.after).c_str(),
                      e.seconds);
        return std::string(std::isinf(e.gapMm) ? "-" : text);
    };
    std::printf("closest approach of the hands (mm; negative: they overlap), every frame at 30 fps and each item's first and last key:\n");
    std::vector<std::string> warnings;
    for (VerbVersion v : {VerbVersion::Point, VerbVersion::Vector, VerbVersion::Animator, VerbVersion::Uninflected}) {
        std::optional<Timeline> built = timelineUnlessFilesMissing(world, story, v, timing, "checked");
        if (!built) continue;
        const TimelineClip clip(signer.rig(), std::move(*built));
        const Timeline& t = clip.timeline();
        const ClearanceSummary summary = checkClearance(t, clearanceFrames(signer.rig(), clip));
        std::printf("  %s: at transitions %s; in signs %s; in signs where they touch %s\n", toString(v).c_str(),
                    place(t, summary.handsAtTransitions).c_str(), place(t, summary.handsInSigns).c_str(),
                    place(t, summary.handsInContactSigns).c_str());
        std::printf("  %*s  a hand and the body %s; in signs that touch it %s\n", static_cast<int>(toString(v).size()), "",
                    place(t, summary.body).c_str(), place(t, summary.bodyInContactSigns).c_str());
        for (const ClearanceViolation& violation : summary.violations) {
            char text[400];
            const char* advice = violation.transition ? ""
                                 : violation.contact
                                     ? "; the sign touches there, but a touch brings the hand to the surface, not through it"
                                     : "; if the sign touches there on purpose, say so (\"contact\")";
            std::snprintf(text, sizeof text, "%s: %s: %s %.1f mm apart at %.2f s (%.1f mm allowed)%s", toString(v).c_str(),
                          describeClearancePlace(t, violation.before, violation.after).c_str(),
                          violation.contact ? (violation.hands ? "the hands sink into each other," : "a hand sinks into the body,")
                          : violation.hands ? "the hands interpenetrate,"
                                            : "a hand is in the body,",
                          violation.gapMm, violation.seconds, violation.allowedMm, advice);
            warnings.push_back(text);
        }
    }
    for (const std::string& w : warnings) std::printf("warning: %s\n", w.c_str());
}

// `--check`: the pace and peak speeds of each version (app/story_timing.hpp); true when a
// limit is broken.
bool reportPace(const StoryWorld& world, const Story& story, const TimelineOptions& timing, const std::string& preset) {
    const Signer signer(world.scenes);
    std::printf("timing (%s): the telling (first to last sign), its pace, and the posed signer's peak speeds:\n",
                preset.c_str());
    std::vector<std::string> warnings;
    for (VerbVersion v : {VerbVersion::Point, VerbVersion::Vector, VerbVersion::Animator, VerbVersion::Uninflected}) {
        std::optional<Timeline> built = timelineUnlessFilesMissing(world, story, v, timing, "measured");
        if (!built) continue;
        const TimelineClip clip(signer.rig(), std::move(*built));
        const StoryPace pace = measurePace(signer.rig(), clip);
        const TimelineMeasures& m = pace.measures;
        std::printf("  %s: %.2f s (telling %.2f s): %.2f signs/s (%d signs)", toString(v).c_str(), m.durationSeconds,
                    m.tellingSeconds, m.signsPerSecond(), m.signs);
        if (m.letters > 0) std::printf(", %.2f letters/s (%d letters)", m.lettersPerSecond(), m.letters);
        std::printf(", pauses %.1f %%; peak wrist %.2f m/s (%.2f s), peak head %.0f deg/s (%.2f s)\n", 100.0 * m.pauseShare(),
                    pace.peakWristMmPerSecond / 1000.0, pace.peakWristSeconds, pace.peakHeadDegreesPerSecond,
                    pace.peakHeadSeconds);
        for (const std::string& w : paceWarnings(pace)) warnings.push_back(toString(v) + ": " + w);
    }
    for (const std::string& w : warnings) std::printf("warning: %s\n", w.c_str());
    return !warnings.empty();
}

// The timing a story is told with: its `timing` object, or --timing's preset instead.
TimelineOptions storyTiming(const StoryOptions& o, const Story& story, std::string* described = nullptr) {
    StoryTiming timing = story.timing;
    if (!o.timing.empty()) timing = StoryTiming{o.timing, {}, 0};
    if (described) *described = describeTiming(timing);
    return timelineOptionsFor(timing, o.rate);
}

void renderStory(const StoryOptions& o, const StoryWorld& world, const Story& story, VerbVersion version) {
    ClipOutput output = checkClipOutput(o.outPath, o.size, o.fps, o.msaa, o.device, o.quiet);
    output.framing = *signer::parseCameraFraming(o.camera);
    const TimelineOptions timing = storyTiming(o, story);
    const Signer signer(world.scenes);
    const TimelineClip clip(signer.rig(), buildTimeline(story, version, world.sources(story), timing));
    // The still: the middle of the first verb (where the versions differ), else the middle.
    double stillSeconds = 0.5 * clip.durationSeconds();
    for (const TimelineSpan& span : clip.timeline().spans)
        if (span.kind == SpanKind::Verb) {
            stillSeconds = 0.5 * (span.startSeconds + span.endSeconds);
            break;
        }
    const std::uint64_t frames = renderClipToOutput(output, signer, clip, stillSeconds);
    if (o.annotations) {
        // Beside the clip, as a study writes them (docs/study.md, "Eye-tracking regions", "ELAN files").
        const fs::path base = fs::path(output.out).replace_extension();
        const signer::ScreenRegionModel model(signer.avatar(), signer.rig());
        writeFileAtomic(base.string() + ".regions.csv",
                        signer::screenRegionsCsv(signer.avatar(), signer.rig(), model, {&clip}, {}, output.frameRate.value(),
                                                 output.size.width, output.size.height, 1, 1));
        ElanDocumentOptions elan;
        elan.mediaUrl = "./" + output.out.filename().string();  // ELAN resolves "./" and "../" against the .eaf's folder
        elan.framesPerSecond = output.frameRate.value();
        for (const StorySentence& sentence : story.sentences) elan.sentenceGlosses.push_back(sentence.gloss);
        writeFileAtomic(base.string() + ".eaf", elanDocument({{"", &clip.timeline()}}, elan));
    }
    std::printf("%s: \"%s\" (%s), %llu frame%s, %.1f s\n", output.out.string().c_str(), story.title.c_str(),
                toString(version).c_str(), static_cast<unsigned long long>(frames), frames == 1 ? "" : "s",
                clip.durationSeconds());
}

}  // namespace

void registerStoryCommands(Commands& commands) {
    auto o = std::make_shared<StoryOptions>();
    CLI::App* story = commands.root.add_subcommand(
        "story",
        "A story in gloss (docs/stories.md): check it, print its timeline, or render the signer telling\n"
        "it in one version. The four versions differ only inside the verbs; every other frame is\n"
        "identical. Signs come from SCENES/lexicon/, verbs from SCENES/verbs.json.\n"
        "Examples:\n"
        "  signstim story scenes/stories/story-01.json --check\n"
        "  signstim story my-story.json --version point --out point.mp4\n"
        "  signstim story my-story.json --version animator --json > timeline.json");
    story->add_option("FILE", o->file, "Story file (JSON)")->required();
    story->add_option("--version", o->version, "point | vector | animator | uninflected");
    auto* check = story->add_flag("--check", o->check,
                                  "Only check: the story, its signs, letters and verbs, in all four versions (exit 2 "
                                  "naming file:line:column); then report how close the hands come to each other and "
                                  "to the body (warnings where they interpenetrate), and each version's duration, "
                                  "signs/s, letters/s, pause share and peak wrist and head speeds (warnings beyond "
                                  "SPEC 6.2-6.3)");
    auto* json = story->add_flag("--json", o->json, "Print the timeline of --version as JSON")->excludes(check);
    story->add_option("--out", o->outPath, "FILE.mp4, FILE.png (a still of the first verb) or a folder of frames")
        ->excludes(check)
        ->excludes(json);
    story->add_option("--size", o->size, "Image size WxH (even for .mp4)")->capture_default_str();
    story->add_option("--fps", o->fps, "Frame rate: 30, 25, 30000/1001 ...")->capture_default_str();
    story->add_option("--msaa", o->msaa, "Multisampling: 1 or 4")->capture_default_str();
    story->add_option("--camera", o->camera,
                      "Camera preset: waist-up (the signing space) or face (a close-up of the head, neck and "
                      "shoulders, for the non-manuals)")
        ->check(CLI::IsMember({"waist-up", "face"}))
        ->capture_default_str();
    story->add_option("--device", o->device, "Vulkan device: name substring or index (see `signstim devices`)");
    story->add_option("--rate", o->rate,
                      "Signing speed relative to the timing model (0.1 to 4; 1: ~1.7 signs/s, docs/stories.md); "
                      "the wrist speed limit holds at any rate")
        ->capture_default_str();
    story->add_option("--timing", o->timing,
                      "Timing preset instead of the story's `timing`: natural (SPEC 6.3) or legacy (the timing "
                      "before issue 21, for comparison)")
        ->check(CLI::IsMember({"natural", "legacy"}));
    story->add_flag("--strict", o->strict,
                    "With --check: exit 2 when a timing limit is broken (pace, letters/s, peak wrist or head speed)")
        ->needs(check);
    story->add_option("--scenes", o->scenesDir,
                      "Data directory (default: $SIGNSTIM_SCENES, else the scenes/ installed beside signstim)");
    story->add_option("--lexicon", o->lexiconFile,
                      "A lab's own lexicon (a file or a folder of .json files) on top of SCENES/lexicon/: its signs are "
                      "added, and replace default signs of the same gloss (--check lists them)");
    story->add_flag("--quiet", o->quiet, "No progress on stderr");
    story->add_flag("--annotations", o->annotations,
                    "With --out FILE.mp4: also write FILE.regions.csv (eye-tracking regions of every frame) and "
                    "FILE.eaf (ELAN annotations), as a study writes them (docs/study.md)");
    story->callback([o] {
        requireInRange(o->rate, 0.1, 4.0, "--rate");
        if (!o->check && !o->json && o->outPath.empty())
            throw commandLineError("--out", "say what to do: --check, --json or --out FILE");
        if (o->annotations && fs::path(o->outPath).extension() != ".mp4")
            throw commandLineError("--annotations", "goes with --out FILE.mp4 (the regions and ELAN file sit beside the clip)");
        std::optional<VerbVersion> version;
        if (!o->check) version = requireVersion(*o);
        StoryWorld pacedWorld(o->scenesDir, o->lexiconFile);
        // Issue 21: transitions paced by the path the signer's hands take (detours included).
        const auto pacingSigner = std::make_shared<const Signer>(pacedWorld.scenes);
        pacedWorld.transitionPacer = transitionPacer(pacingSigner);
        // Issue 21: verbs signed within the signer's comfortable reach.
        pacedWorld.reach = signerReach(pacingSigner->rig());
        const StoryWorld& world = pacedWorld;
        const Story story = world.loadStory(o->file);
        std::string preset;
        const TimelineOptions timing = storyTiming(*o, story, &preset);
        if (o->check) {
            double seconds = 0.0;
            int verbs = 0;
            std::string nonManuals;  // issue 23: what the markers and blinks make (the same in every version)
            std::vector<std::string> missingAnimator;
            for (VerbVersion v : {VerbVersion::Point, VerbVersion::Vector, VerbVersion::Animator, VerbVersion::Uninflected}) {
                try {
                    const Timeline t = buildTimeline(story, v, world.sources(story), timing);
                    seconds = t.durationSeconds;
                    nonManuals = describeNonManuals(story, t);
                    verbs = 0;
                    for (const TimelineSpan& span : t.spans) verbs += span.kind == SpanKind::Verb;
                } catch (const MissingAnimatorFiles& e) {
                    missingAnimator = e.files();  // only the animator version needs them
                }
            }
            std::printf("%s: ok: \"%s\", %zu characters, %zu sentences, %d verbs, %zu questions, %.1f s in every version%s\n",
                        o->file.c_str(), story.title.c_str(), story.characters.size(), story.sentences.size(), verbs,
                        story.questions.size(), seconds, missingAnimator.empty() ? "" : " but animator");
            if (!nonManuals.empty()) std::printf("%s\n", nonManuals.c_str());
            if (!missingAnimator.empty()) {
                std::printf("warning: the animator version cannot be rendered: %zu keyframe file%s missing (point, vector "
                            "and uninflected do not need them); `signstim animator draft %s` writes starting files:\n",
                            missingAnimator.size(), missingAnimator.size() == 1 ? " is" : "s are", o->file.c_str());
                for (const std::string& f : missingAnimator) std::printf("  %s\n", f.c_str());
            }
            for (const std::string& f : world.draftAnimatorFiles(story))
                std::printf("note: %s is a draft (\"draft\": true): a study refuses it unless --allow-draft-animator\n", f.c_str());
            for (const std::string& note : world.copiedDraftNotes(story)) std::printf("warning: %s\n", note.c_str());
            for (const std::string& note : world.lexiconOverrideNotes()) std::printf("note: %s\n", note.c_str());
            for (const std::string& note : world.fingerspellingNotes(story)) std::printf("note: %s\n", note.c_str());
            std::fflush(stdout);
            reportClearance(world, story, timing);
            const bool broken = reportPace(world, story, timing, preset);
            std::fflush(stdout);
            if (broken && o->strict)
                throw InputError(o->file, 0, "timing", "a timing limit is broken (the warnings above; --strict)");
            return;
        }
        if (o->json) {
            writeStandardOutput(formatTimelineJson(buildTimeline(story, *version, world.sources(story), timing)));
            return;
        }
        renderStory(*o, world, story, *version);
    });
}

}  // namespace signstim::app
