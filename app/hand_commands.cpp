// `signstim hand shapes|pose|from-sensors` and `signstim bench hand`: the kinematic hand of
// SPEC §1–§2 from the command line.
#include "app/cli_values.hpp"
#include "app/commands.hpp"
#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "hand/hand_model.hpp"
#include "hand/sensor_hand.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/verbs/sensor_io.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

namespace signstim::app {
namespace {

struct HandOptions {
    std::string scenesDir;
    std::string shapesFile;  // default <scenes>/handshapes.json
    std::string shape;
    std::string side = "right";
    float handLengthMm = 190.0f;
    float handBreadthMm = 85.0f;
    bool json = false;
    std::string samples;
    std::string calibration;
    std::string out;
    double seconds = 2.0;
};

hand::HandModel modelFor(const HandOptions& o) {
    requireInRange(o.handLengthMm, 100.0, 300.0, "--hand-length", "mm");
    requireInRange(o.handBreadthMm, 40.0, 150.0, "--hand-breadth", "mm");
    return hand::buildHandModel(hand::scaledHandDimensions(o.handLengthMm, o.handBreadthMm));
}

stimuli::HandshapeLibrary library(const HandOptions& o, const hand::HandModel& model) {
    return stimuli::loadHandshapes(stimuli::handshapesFile(o.shapesFile, o.scenesDir), model);
}

void addLibraryOptions(CLI::App* command, const std::shared_ptr<HandOptions>& o) {
    command->add_option("--scenes", o->scenesDir,
                        "Data directory (default: $SIGNSTIM_SCENES, else the scenes/ beside signstim, else the "
                        "source tree's)");
    command->add_option("--shapes", o->shapesFile, "Handshape file (default: SCENES/handshapes.json)");
}

nlohmann::json vec(const glm::vec3& v) {
    auto r = [](float x) { return std::round(static_cast<double>(x) * 1e4) / 1e4 + 0.0; };
    return nlohmann::json::array({r(v.x), r(v.y), r(v.z)});
}

void runShapes(const HandOptions& o) {
    const hand::HandModel model = modelFor(o);
    for (const stimuli::Handshape& shape : library(o, model).shapes) {
        std::printf("%s\t%s\n", shape.name.c_str(), shape.aslLexLabel.empty() ? "-" : shape.aslLexLabel.c_str());
    }
}

void runPose(const HandOptions& o) {
    const hand::HandModel model = modelFor(o);
    // A copy: a reference into the temporary library would dangle (found by ASan).
    const stimuli::Handshape shape = library(o, model).at(o.shape);
    const hand::Side side = o.side == "left" ? hand::Side::Left : hand::Side::Right;
    const hand::HandPose pose = hand::forwardKinematics(model, shape.controls, side);
    // Never print a non-finite number (JSON would say null): the controls are range-checked on
    // load, so this is a guard, and it names the shape and file.
    const auto finite = [](const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); };
    bool allFinite = true;
    for (const hand::RigidTransform& body : pose.bodies)
        allFinite = allFinite && finite(body.position) && std::isfinite(body.rotation.w) && finite({body.rotation.x, body.rotation.y, body.rotation.z});
    for (const glm::vec3& tip : pose.tips) allFinite = allFinite && finite(tip);
    if (!allFinite)
        throw InputError(stimuli::handshapesFile(o.shapesFile, o.scenesDir).string(), 0, "handshape '" + shape.name + "'",
                         "the pose of this shape is not finite; nothing is printed");
    if (o.json) {
        nlohmann::json out;
        out["side"] = o.side;
        out["shape"] = shape.name;
        nlohmann::json joints = nlohmann::json::array();
        for (int b = 0; b < hand::kBodyCount; ++b) {
            const hand::RigidTransform& t = pose.bodies[b];
            const glm::quat q = t.rotation.w < 0.0f ? -t.rotation : t.rotation;  // canonical sign
            auto r = [](float x) { return std::round(static_cast<double>(x) * 1e6) / 1e6 + 0.0; };
            joints.push_back({{"name", hand::boneName(side, static_cast<hand::Body>(b))},
                              {"position", vec(t.position)},
                              {"rotation", {r(q.w), r(q.x), r(q.y), r(q.z)}}});
        }
        out["joints"] = joints;
        for (int d = 0; d < hand::kDigitCount; ++d) {
            out["tips"][std::string(hand::digitName(static_cast<hand::Digit>(d)))] = vec(pose.tips[d]);
        }
        std::printf("%s\n", out.dump(2).c_str());
        return;
    }
    std::printf("%s hand, shape %s (%s), palm frame, mm\n", o.side.c_str(), shape.name.c_str(),
                shape.aslLexLabel.empty() ? "no ASL-LEX label" : shape.aslLexLabel.c_str());
    for (int b = 0; b < hand::kBodyCount; ++b) {
        const glm::vec3 p = pose.bodies[b].position;
        std::printf("  %-26s %8.2f %8.2f %8.2f\n", std::string(hand::boneName(side, static_cast<hand::Body>(b))).c_str(),
                    p.x, p.y, p.z);
    }
    for (int d = 0; d < hand::kDigitCount; ++d) {
        const glm::vec3 p = pose.tips[d];
        std::printf("  tip %-22s %8.2f %8.2f %8.2f\n", std::string(hand::digitName(static_cast<hand::Digit>(d))).c_str(),
                    p.x, p.y, p.z);
    }
}

void runFromSensors(const HandOptions& o) {
    const std::filesystem::path out(o.out);
    const std::string extension = out.extension().string();
    if (extension != ".json" && extension != ".csv") {
        throw commandLineError("--out", "must end in .json or .csv, got '" + o.out + "'");
    }
    const hand::SensorCalibration calibration = stimuli::loadSensorCalibration(o.calibration);
    const std::vector<stimuli::SensorSample> samples = stimuli::loadSensorSamples(o.samples);
    std::vector<hand::SensorHandFrame> frames;
    frames.reserve(samples.size());
    for (const stimuli::SensorSample& s : samples) frames.push_back(hand::sensorHand(calibration, s.readings));
    stimuli::checkSensorHandFinite(samples, frames, o.samples);
    const std::string text = extension == ".json"
                                 ? stimuli::formatSensorHandJson(calibration.side, samples, frames)
                                 : stimuli::formatSensorHandCsv(calibration.side, samples, frames);
    writeFileAtomic(out, text);
    std::fprintf(stderr, "signstim: %zu samples -> %s\n", samples.size(), o.out.c_str());
}

// Deterministic control sets that exercise every correlation and clamp (no scenes/ needed).
std::vector<hand::HandControls> benchControls() {
    std::vector<hand::HandControls> controls(256);
    for (std::size_t i = 0; i < controls.size(); ++i) {
        const float t = static_cast<float>(i) / static_cast<float>(controls.size());
        hand::HandControls& c = controls[i];
        c.thumb = {-25.0f + 145.0f * t, 10.0f + 80.0f * std::fmod(3.0f * t, 1.0f), 60.0f * std::fmod(5.0f * t, 1.0f),
                   80.0f * std::fmod(7.0f * t, 1.0f)};
        for (int f = 0; f < hand::kFingerCount; ++f) {
            c.fingers[f] = {-25.0f + 55.0f * std::fmod(t + 0.1f * f, 1.0f), std::fmod(2.0f * t + 0.2f * f, 1.0f),
                            std::fmod(3.0f * t + 0.3f * f, 1.0f)};
        }
    }
    return controls;
}

template <class Body>
double measure(double seconds, Body&& body) {
    using Clock = std::chrono::steady_clock;
    std::size_t count = 0;
    const auto start = Clock::now();
    double elapsed = 0.0;
    do {
        for (int i = 0; i < 4096; ++i) body(count++);
        elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    } while (elapsed < seconds);
    return static_cast<double>(count) / elapsed;
}

void runBench(const HandOptions& o) {
    if (!(o.seconds > 0.0 && o.seconds <= 600.0)) throw commandLineError("--seconds", "must be in (0, 600]");
    const hand::HandModel model = hand::buildHandModel();
    const std::vector<hand::HandControls> controls = benchControls();
    volatile float sink = 0.0f;  // keeps the work observable
    const double poses = measure(o.seconds, [&](std::size_t i) {
        const hand::HandPose pose = hand::forwardKinematics(model, controls[i & 255], (i & 256) ? hand::Side::Left : hand::Side::Right);
        sink = sink + pose.tips[2].x;
    });
    const double interpolated = measure(o.seconds, [&](std::size_t i) {
        const hand::HandControls c = hand::interpolate(controls[i & 255], controls[(i + 1) & 255], 0.37f);
        const hand::HandPose pose = hand::forwardKinematics(model, c, hand::Side::Right);
        const auto local = hand::localTransforms(pose);
        sink = sink + local[6].position.z;
    });
    const hand::SensorCalibration calibration = hand::calibrationForModel(model, hand::Side::Right);
    std::vector<hand::SensorReadings> readings;
    for (const auto& c : controls) {
        readings.push_back(hand::synthesizeSensorReadings(model, hand::forwardKinematics(model, c, hand::Side::Right), calibration));
    }
    const double sensorFrames = measure(o.seconds, [&](std::size_t i) {
        const hand::SensorHandFrame frame = hand::sensorHand(calibration, readings[i & 255]);
        sink = sink + frame.joints[1].proximalJoint.x;
    });
    std::printf("hand kinematics, one thread, %.1f s per measurement\n", o.seconds);
    std::printf("  controls -> pose (jointAngles + forwardKinematics): %12.0f poses/s  (%.0f ns/pose)\n", poses, 1e9 / poses);
    std::printf("  interpolate + pose + local transforms:             %12.0f poses/s  (%.0f ns/pose)\n", interpolated,
                1e9 / interpolated);
    std::printf("  sensor hand (6 readings -> joints + 16 boxes):      %12.0f frames/s (%.0f ns/frame)\n", sensorFrames,
                1e9 / sensorFrames);
    std::printf("  target: >= 1,000,000 poses/s -> %s\n", poses >= 1e6 ? "met" : "NOT met");
}

}  // namespace

void registerHandCommands(Commands& commands) {
    auto o = std::make_shared<HandOptions>();
    CLI::App* handCommand = commands.root.add_subcommand(
        "hand", "The kinematic hand: handshape library, poses, and the sensor-driven hand (SPEC §1–§2)");
    handCommand->require_subcommand(1);

    CLI::App* shapes = handCommand->add_subcommand("shapes", "List the handshapes: one per line, name <TAB> ASL-LEX label ('-' if none)");
    addLibraryOptions(shapes, o);
    shapes->callback([o] { runShapes(*o); });

    CLI::App* pose = handCommand->add_subcommand(
        "pose",
        "Pose a handshape and print its 16 bones (VRM names) and fingertips in the palm frame, mm:\n"
        "origin at the base of the palm, +z toward the fingers, +x out of the palm, +y toward the\n"
        "thumb of a right hand (the left hand is its mirror, y -> -y).");
    addLibraryOptions(pose, o);
    pose->add_option("--shape", o->shape, "Handshape name, e.g. A, bent-B, 5 (see `signstim hand shapes`)")->required();
    pose->add_option("--side", o->side, "Which hand")->check(CLI::IsMember({"right", "left"}));
    pose->add_option("--hand-length", o->handLengthMm, "Hand length, mm (SPEC §1.2 default 190)");
    pose->add_option("--hand-breadth", o->handBreadthMm, "Hand breadth, mm (SPEC §1.2 default 85)");
    pose->add_flag("--json", o->json,
                   "JSON: {\"side\", \"shape\", \"joints\": [{\"name\", \"position\": [x,y,z], \"rotation\": "
                   "[w,x,y,z]}], \"tips\": {\"thumb\": [x,y,z], ...}}");
    pose->callback([o] { runPose(*o); });

    CLI::App* fromSensors = handCommand->add_subcommand(
        "from-sensors",
        "Rebuild the 16-segment hand from six 6-DOF sensors (van Polanen et al.; SPEC §2).\n"
        "SAMPLES.csv: header time,sensor,x,y,z,azimuth,elevation,roll; sensors hand, thumb, index,\n"
        "middle, ring, little (or 0..5); s, mm, degrees. CAL.json: see stimuli/verbs/sensor_io.hpp.\n"
        "Writes per sample the joints A-D of each digit and the 8 vertices of each segment.");
    fromSensors->add_option("samples", o->samples, "Samples CSV")->required();
    fromSensors->add_option("--calibration", o->calibration, "Calibration JSON")->required();
    fromSensors->add_option("--out", o->out, "Output file, .json or .csv (written atomically)")->required();
    fromSensors->callback([o] { runFromSensors(*o); });

    CLI::App* bench = commands.bench.add_subcommand(
        "hand", "Hand poses per second on one thread (target >= 1 million; see BENCHMARKS.md)");
    bench->add_option("--seconds", o->seconds, "Duration of each measurement (default 2)");
    bench->callback([o] { runBench(*o); });
}

}  // namespace signstim::app
