#pragma once
// Each area of the `signstim` command registers its subcommands here. The callbacks do the
// work and may throw signstim::InputError (exit 2) or EnvironmentError (exit 3); main()
// turns those into one clear message.
#include <CLI/CLI.hpp>

namespace signstim::app {

struct Commands {
    CLI::App& root;   // `signstim`
    CLI::App& bench;  // `signstim bench`
};

void registerRenderCommands(Commands& commands);  // render-gltf
void registerRenderBenchCommands(Commands& commands);  // devices, bench render
void registerHandCommands(Commands& commands);    // hand ..., bench hand
void registerVerbCommands(Commands& commands);    // train, verb, evaluate
void registerAvatarCommands(Commands& commands);  // avatar build, handshapes, pose
void registerDemoCommand(Commands& commands);     // demo (the main job until the study exists)
void registerStoryCommands(Commands& commands);   // story (check, timeline, render)
void registerSignCommand(Commands& commands);     // sign (one lexicon sign: its code, checks, render)
void registerStudyCommands(Commands& commands);   // study (render, check, verify, merge), bench study
void registerAnalysisCommands(Commands& commands);  // analyze, simulate-results

}  // namespace signstim::app
