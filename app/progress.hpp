#pragma once
// The one progress reporter of the rendering commands (study, story, verb, demo, render-gltf):
// on a terminal one line rewritten in place with a bar, otherwise a line now and then (and one
// per finished step) for logs; the time left estimated from the work done so far. Nothing when
// quiet. Progress goes to stderr; stdout keeps the command's result.
#include <chrono>
#include <string>

namespace signstim::app {

class ProgressReporter {
public:
    // `label`: "signstim study"; `total`: the work (frames, or estimated images to draw).
    ProgressReporter(std::string label, double total, bool quiet);
    ~ProgressReporter();
    ProgressReporter(const ProgressReporter&) = delete;
    ProgressReporter& operator=(const ProgressReporter&) = delete;

    // `done` of the total; `what`: the item being worked on ("story-03 (2/12)"). Printed at most
    // every 250 ms on a terminal, every 10 s in a log.
    void update(double done, const std::string& what);
    // A step finished (a unit, a clip): printed at once; in a log as its own line ending "done".
    void stepDone(double done, const std::string& what);
    // Ends the terminal's line (also done by the destructor).
    void end();

    double elapsedSeconds() const;

private:
    void print(const std::string& what, bool step);

    std::string label_;
    double total_, done_ = 0.0;
    bool quiet_, terminal_, printed_ = false, ended_ = false;
    std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace signstim::app
