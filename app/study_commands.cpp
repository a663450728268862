// `signstim study`: the main job (docs/study.md). `study [FILE] --out DIR` renders a study;
// `study verify DIR` checks a study folder against its manifest; `study merge DIR...` joins the
// folders of a sharded run. `bench study` measures the study against the naive cost.
#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "app/study_runner.hpp"
#include "common/error.hpp"
#include "stimuli/scenes_path.hpp"
#include "stimuli/study/study.hpp"
#include "stimuli/study/study_folder.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>

namespace signstim::app {
namespace {

namespace fs = std::filesystem;

struct StudyCommandOptions {
    std::string file;
    std::string out;
    bool quick = false;
    bool check = false;
    bool frames = false;
    std::string experiment;
    unsigned jobs = 0;
    std::string shard;
    std::string device;
    std::string scenesDir;
    std::string lexicon;
    bool allowDraftAnimator = false;
    bool quiet = false;
    bool force = false;
};

StudyRunOptions runOptions(const StudyCommandOptions& o) {
    StudyRunOptions r;
    r.studyFile = o.file;
    r.out = o.out;
    r.quick = o.quick;
    r.jobs = o.jobs;
    r.pngFrames = o.frames;
    r.experiment = o.experiment;
    r.device = o.device;
    r.scenesDir = o.scenesDir;
    r.lexicon = o.lexicon;
    r.allowDraftAnimator = o.allowDraftAnimator;
    r.quiet = o.quiet;
    r.force = o.force;
    std::tie(r.shardIndex, r.shardCount) = o.shard.empty() ? shardFromEnvironment() : parseShard(o.shard);
    return r;
}

void printSummary(const StudyRunOptions& r, const StudyRunReport& report) {
    std::printf("%s: %zu of %zu units rendered, %zu already complete%s, %.1f s\n", r.out.string().c_str(), report.rendered,
                report.unitsInShard, report.skipped,
                r.shardCount > 1 ? (" (shard " + std::to_string(r.shardIndex) + "/" + std::to_string(r.shardCount) + ")").c_str()
                                 : "",
                report.totalSeconds);
    if (report.complete) {
        std::printf("study complete: review page %s\n  manifest %s; check it with `signstim study verify %s`\n",
                    (r.out / "index.html").string().c_str(), (r.out / "manifest.json").string().c_str(),
                    r.out.string().c_str());
        if (report.experiment)
            std::printf("  jsPsych experiment %s?participant=%s (docs/experiment.md)\n",
                        (r.out / "experiment" / "index.html").string().c_str(), report.firstParticipant.c_str());
    } else {
        std::printf("%zu of %zu units are still missing (other shards); when every shard has finished, run\n"
                    "  signstim study merge %s [OTHER-SHARD-FOLDERS...]\n",
                    report.missing.size(), report.units, r.out.string().c_str());
    }
}

double cpuSeconds(int who) {
    rusage usage{};
    ::getrusage(who, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

}  // namespace

void registerStudyCommands(Commands& commands) {
    auto o = std::make_shared<StudyCommandOptions>();
    CLI::App* study = commands.root.add_subcommand(
        "study",
        "The main job: a study file (docs/study.md) -> every stimulus clip (12 stories x 4 versions,\n"
        "side-by-side clips of the 4 versions), every participant's schedule, exports for PsychoPy,\n"
        "OpenSesame, Gorilla and jsPsych, a manifest and a review page (index.html), in one folder;\n"
        "with --experiment jspsych also a ready-to-run jsPsych experiment (experiment/index.html).\n"
        "Without FILE: the default study, SCENES/studies/default.json.\n"
        "A re-run skips what is complete and unchanged; an interrupted run leaves no broken file.\n"
        "Examples:\n"
        "  signstim study --out my-study --quick        (small and fast: look at index.html)\n"
        "  signstim study --out my-study --quick --experiment jspsych   (then open experiment/index.html)\n"
        "  signstim study my-study.json --check\n"
        "  signstim study my-study.json --out out/ --jobs 8\n"
        "  signstim study my-study.json --out out/ --shard 0/4    (one of 4 machines; then `study merge`)\n"
        "  signstim study verify out/");
    study->add_option("FILE", o->file, "Study file (JSON); default SCENES/studies/default.json");
    auto* check = study->add_flag("--check", o->check,
                                  "Only check the study file, its stories and sentences in every version (exit 2 naming file:line)");
    study->add_option("--out", o->out, "Output folder (created; re-runs complete it)")->excludes(check);
    study->add_flag("--quick", o->quick,
                    "Render with the study's quick settings (default 320x240, 15 fps, MSAA 1): minutes, for a first look");
    study->add_flag("--frames", o->frames, "Also write each clip's PNG frames (frames/...)");
    study->add_option("--experiment", o->experiment,
                      "jspsych: also write experiment/, a jsPsych 8 experiment that runs each participant's session from\n"
                      "disk or any web server and saves their answers as CSV (docs/experiment.md; needs jsPsych, fetched by\n"
                      "scripts/setup.sh). none: no experiment, whatever the study file's outputs.experiment says")
        ->check(CLI::IsMember({"jspsych", "none"}));
    study->add_option("--jobs", o->jobs,
                      "Encoders running at once beside the renderer (default: the machine's cores; at least the number of versions)")
        ->check(CLI::Range(1u, 256u));
    study->add_option("--shard", o->shard,
                      "I/N: render only units I, I+N, ... of the sorted list (0-based; default from SLURM_ARRAY_TASK_ID and "
                      "SLURM_ARRAY_TASK_COUNT); then `study merge`");
    study->add_option("--device", o->device, "Vulkan device: name substring or index (see `signstim devices`)");
    study->add_option("--scenes", o->scenesDir,
                      "Data directory (default: $SIGNSTIM_SCENES, else the scenes/ installed beside signstim)");
    study->add_option("--lexicon", o->lexicon,
                      "A lab's own lexicon (a file or a folder of .json files) on top of SCENES/lexicon/: its signs are "
                      "added, and replace default signs of the same gloss (--check lists them)");
    study->add_flag("--allow-draft-animator", o->allowDraftAnimator,
                    "Use animator files marked \"draft\" (starting points from `signstim animator draft`); the "
                    "manifest and the review page list them");
    study->add_flag("--quiet", o->quiet, "No progress on stderr");
    study->add_flag("--force", o->force,
                    "Write into an --out folder that holds other files (they are kept: nothing is deleted that signstim did "
                    "not write)");

    auto verifyDir = std::make_shared<std::string>();
    CLI::App* verify = study->add_subcommand(
        "verify", "Check every file of a study folder against its manifest (size and SHA-256) and that no unit is missing");
    verify->add_option("DIR", *verifyDir, "Study folder")->required();
    verify->callback([verifyDir, o] {
        const stimuli::StudyVerification result = stimuli::verifyStudyFolder(*verifyDir);
        if (!o->quiet)
            std::fprintf(stderr, "signstim study verify: %zu of %zu files match the manifest\n", result.checked, result.listed);
        const std::vector<std::string>& problems = result.problems;
        if (problems.empty()) {
            std::printf("%s: verified\n", verifyDir->c_str());
            return;
        }
        std::string message = std::to_string(problems.size()) + " problem" + (problems.size() == 1 ? "" : "s") + ":";
        for (const std::string& p : problems) message += "\n  " + p;
        throw InputError(*verifyDir, 0, "", message);
    });

    auto mergeDirs = std::make_shared<std::vector<std::string>>();
    auto mergeInto = std::make_shared<std::string>();
    CLI::App* merge = study->add_subcommand(
        "merge",
        "Join the folders of a sharded run (`--shard I/N`) into one (the first, or --into) and finish it:\n"
        "exports, review page, manifest. With shards writing to one shared folder, give just that folder.");
    merge->add_option("DIR", *mergeDirs, "Study folders of the shards")->required();
    merge->add_option("--into", *mergeInto, "Folder to merge into (default: the first DIR)");
    auto mergeExperiment = std::make_shared<std::string>();
    merge->add_option("--experiment", *mergeExperiment,
                      "jspsych: also write the jsPsych experiment (written anyway when a shard's run asked for it)")
        ->check(CLI::IsMember({"jspsych"}));
    merge->callback([mergeDirs, mergeInto, mergeExperiment, o] {
        std::vector<fs::path> dirs(mergeDirs->begin(), mergeDirs->end());
        const fs::path target = mergeInto->empty() ? dirs.front() : fs::path(*mergeInto);
        const stimuli::StudyMerge merged = stimuli::mergeStudyFolders(dirs, target, *mergeExperiment);
        const stimuli::StudyFolderState& report = merged.state;
        if (!o->quiet)
            std::fprintf(stderr, "signstim study merge: %zu unit%s copied into %s\n", merged.copied, merged.copied == 1 ? "" : "s",
                         target.string().c_str());
        if (!report.complete) {
            std::string message = std::to_string(report.missing.size()) + " of " + std::to_string(report.units) +
                                  " units are in none of the folders:";
            for (const std::string& unit : report.missing) message += " " + unit;
            throw InputError(target.string(), 0, "", message + " (run the shards that render them)");
        }
        std::printf("%s: complete: review page %s; check it with `signstim study verify %s`\n", target.string().c_str(),
                    (target / "index.html").string().c_str(), target.string().c_str());
        if (report.experiment)
            std::printf("  jsPsych experiment %s?participant=%s (docs/experiment.md)\n",
                        (target / "experiment" / "index.html").string().c_str(), report.firstParticipant.c_str());
    });

    study->callback([o, study] {
        if (!study->get_subcommands().empty()) return;
        const StudyRunOptions r = runOptions(*o);
        if (o->check) {
            checkStudy(r);
            return;
        }
        if (o->out.empty()) throw commandLineError("--out", "say where the study goes: --out DIR (or --check)");
        printSummary(r, runStudy(r));
    });

    // ---- bench study ------------------------------------------------------------------------
    auto bench = std::make_shared<StudyCommandOptions>();
    auto full = std::make_shared<bool>(false);
    CLI::App* benchStudy = commands.bench.add_subcommand(
        "study",
        "Wall time of a study (default: the default study at --quick) rendered as `signstim study` does it\n"
        "(frames shared across versions, encoders in parallel) and naively (every story x version drawn\n"
        "in full and encoded one clip after another), per stage, with the share of frames reused.");
    benchStudy->add_option("FILE", bench->file, "Study file (default: SCENES/studies/default.json)");
    benchStudy->add_flag("--full", *full, "Full quality (the study's render settings) instead of quick");
    benchStudy->add_option("--jobs", bench->jobs, "Encoders at once (default: cores)")->check(CLI::Range(1u, 256u));
    benchStudy->add_option("--device", bench->device, "Vulkan device");
    benchStudy->add_option("--scenes", bench->scenesDir, "Data directory");
    benchStudy->add_option("--out", bench->out, "Keep the two study folders here (default: a temporary folder, removed)");
    benchStudy->callback([bench, full] {
        const fs::path base = bench->out.empty()
                                  ? fs::temp_directory_path() / ("signstim-bench-study-" + std::to_string(::getpid()))
                                  : fs::path(bench->out);
        struct Row {
            const char* name;
            StudyRunReport report;
            double encoderCpu, ownCpu;
        };
        std::vector<Row> rows;
        for (const bool share : {true, false}) {
            StudyRunOptions r;
            r.studyFile = bench->file;
            r.out = base / (share ? "shared" : "naive");
            r.quick = !*full;
            r.jobs = share ? bench->jobs : 1;
            r.shareFrames = share;
            r.device = bench->device;
            r.scenesDir = bench->scenesDir;
            r.quiet = ::isatty(STDERR_FILENO) != 1;
            std::error_code ignored;
            fs::remove_all(r.out, ignored);
            const double childrenBefore = cpuSeconds(RUSAGE_CHILDREN), selfBefore = cpuSeconds(RUSAGE_SELF);
            const StudyRunReport report = runStudy(r);
            rows.push_back({share ? "signstim study" : "naive", report, cpuSeconds(RUSAGE_CHILDREN) - childrenBefore,
                            cpuSeconds(RUSAGE_SELF) - selfBefore});
        }
        std::printf("bench study (%s): %zu units\n", *full ? "full quality" : "quick", rows.front().report.units);
        std::printf("| run | wall s | timelines s | render loop s | encoder drain s | documents s | images drawn | clip frames | "
                    "frames reused | signstim CPU s | encoders CPU s |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
        for (const Row& row : rows) {
            const StudyRunReport& r = row.report;
            const double reused =
                r.clipFrames > 0 ? 1.0 - static_cast<double>(r.renderedImages) / static_cast<double>(r.clipFrames) : 0.0;
            std::printf("| %s | %.1f | %.2f | %.1f | %.1f | %.2f | %llu | %llu | %.0f%% | %.1f | %.1f |\n", row.name, r.totalSeconds,
                        r.timelineSeconds, r.renderSeconds, r.encodeWaitSeconds, r.writeSeconds,
                        static_cast<unsigned long long>(r.renderedImages), static_cast<unsigned long long>(r.clipFrames),
                        100.0 * reused, row.ownCpu, row.encoderCpu);
        }
        std::printf("eye-tracking regions and ELAN files (docs/study.md): %.2f s of signstim's time in the study run\n",
                    rows.front().report.annotationSeconds);
        std::printf("speed-up over naive: %.2fx wall (target >= 2x on 2 cores), %.2fx CPU (signstim + encoders)\n",
                    rows[1].report.totalSeconds / rows[0].report.totalSeconds,
                    (rows[1].ownCpu + rows[1].encoderCpu) / (rows[0].ownCpu + rows[0].encoderCpu));
        if (bench->out.empty()) {
            std::error_code ignored;
            fs::remove_all(base, ignored);
        }
    });
}

}  // namespace signstim::app
