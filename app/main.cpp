// The `signstim` command: parses arguments, wires stimuli -> renderer, reports progress.
#include "app/cli_rules.hpp"
#include "app/commands.hpp"
#include "common/cleanup.hpp"
#include "common/error.hpp"
#include "common/standard_output.hpp"

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>

#ifndef SIGNSTIM_VERSION
#define SIGNSTIM_VERSION "0.0.0"
#endif

namespace {

// What a command printed on stdout (JSON, tables) is its result: a write that failed there
// (disk full, /dev/full, a closed pipe) fails the run, with the system's reason for the write
// that failed (common/standard_output.hpp keeps it where stdio would lose it).
int checkStandardOutput() {
    const int error = signstim::flushStandardOutput();
    if (error == 0) return 0;
    std::fprintf(stderr, "signstim: error: cannot write to standard output: %s\n", std::strerror(error));
    return 3;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace signstim;
    // A closed pipe on stdout or stderr (`signstim ... | head`, a dead `tee`) must not kill the
    // run at a printf, skipping the cleanup and orphaning ffmpeg: with SIGPIPE ignored the
    // write fails with EPIPE instead. stdout is checked at the end (exit 3, "Broken pipe");
    // progress lines on stderr are best effort and their failure is ignored (docs/errors.md).
    // Before any thread exists, so every thread ignores it; children get the default back.
    std::signal(SIGPIPE, SIG_IGN);
    // First, before any thread exists: signals then reach only the thread that cleans up.
    startInterruptHandling();
    CLI::App root{
        "signstim — stimulus videos for studies of animated ASL verbs.\n"
        "Renders a signer headless (Vulkan; Mesa lavapipe when no GPU is present) from the data\n"
        "files in scenes/: hand shapes, verb models, stories and study designs.\n",
        "signstim"};
    root.set_version_flag("--version", SIGNSTIM_VERSION);
    root.require_subcommand(1);
    root.footer(
        "\nRun `signstim COMMAND --help` for the options of one command.\n"
        "Exit status: 0 success, 1 bad command line (unknown flag, value out of range), 2 bad input\n"
        "file (the message names the file, line and field), 3 failed read or write, or a missing\n"
        "device or program (no Vulkan device, ffmpeg missing, disk full), 130/143 interrupted by\n"
        "SIGINT/SIGTERM (nothing incomplete is left). docs/errors.md has more.");

    CLI::App* bench = root.add_subcommand(
        "bench", "Measure performance: prints figures and ratios (see BENCHMARKS.md)");
    bench->require_subcommand(1);

    app::Commands commands{root, *bench};
    app::registerDemoCommand(commands);
    app::registerRenderCommands(commands);
    app::registerRenderBenchCommands(commands);
    app::registerHandCommands(commands);
    app::registerAvatarCommands(commands);
    app::registerVerbCommands(commands);
    app::registerStoryCommands(commands);
    app::registerSignCommand(commands);
    app::registerStudyCommands(commands);
    app::registerAnalysisCommands(commands);
    app::requirePlainNumbers(root);

    try {
        root.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        // --help and --version exit 0; every usage mistake exits 1 (CLI11's own codes vary).
        return root.exit(e) == 0 ? 0 : 1;
    } catch (const InputError& e) {
        std::fprintf(stderr, "signstim: error: %s\n", e.what());
        return e.isUsage() ? 1 : 2;
    } catch (const EnvironmentError& e) {
        std::fprintf(stderr, "signstim: error: %s\n", e.what());
        return 3;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "signstim: internal error: %s\n", e.what());
        return 4;
    }
    return checkStandardOutput();
}
