#pragma once
// Human-video versions in a study (issue 24 §2; docs/study.md "Human-video versions"): the
// lab's recordings a study file names (stimuli/study/human_versions.hpp) are probed and hashed
// when the study is loaded (a missing or unreadable one: exit 2 naming the file, the version and
// the pattern), their hashes join the input hash of the units that show them (a changed
// recording renders its unit again), and at render time they are normalised to the study's
// size, rate and format (renderer/video_decoder.hpp, then the study's own encoder): a phase-1
// clip whole, a phase-2 clip into its panel of the side-by-side video.
#include "renderer/video_decoder.hpp"
#include "stimuli/study/study.hpp"

#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace signstim::app {

struct HumanClip {
    std::size_t version = 0;   // index into the listing's versions
    std::string name;          // the human version's name ("human")
    std::filesystem::path path;  // the recording, as resolved against the study file
    std::string sha256;        // of its bytes
    render::VideoProbe probe;
};

// Every unit's recordings, by unit id ("story-03", "likert-05"), in version order.
using HumanClips = std::map<std::string, std::vector<HumanClip>>;

// ---- probes kept between runs ------------------------------------------------------------------
// Probing a recording decodes every frame (ffprobe -count_frames, render::probeVideo): seconds
// per recording, on every load of the study. So the probes are kept in the study folder by the
// SHA-256 of the recording's bytes: a re-run, or a shard rendering into the same folder, probes
// only a recording it has not seen, and a changed recording (other bytes, another hash) is
// probed again. Only probes that found no problem are kept; a missing, unreadable or malformed
// file, or one another signstim version wrote, is an empty cache (everything probed again).
inline constexpr const char* kHumanProbeCacheFile = ".signstim/human-probes.json";

struct HumanProbeCache {
    std::map<std::string, render::VideoProbe> bySha256;
};

// What probes a recording: render::probeVideo (ffprobe), or a test's stand-in.
using VideoProber = std::function<render::VideoProbe(const std::filesystem::path&)>;

HumanProbeCache readHumanProbeCache(const std::filesystem::path& studyFolder);
// The probes of `clips` only (a replaced recording's old entry goes), written atomically.
void writeHumanProbeCache(const std::filesystem::path& studyFolder, const HumanClips& clips);

// `file`'s probe: from `cache` when its bytes' SHA-256 is there, else from `probe` (or
// render::probeVideo when empty), added to `cache` when it found no problem. `sha256` receives
// the hash of a readable file, else is left empty (the probe then says what is wrong).
render::VideoProbe probeRecording(const std::filesystem::path& file, std::string& sha256, HumanProbeCache& cache,
                                  const VideoProber& probe = {});

// ---- the study's recordings --------------------------------------------------------------------

// Probes (through `cache`, probeRecording) and hashes every recording the study names. Throws
// InputError (exit 2) naming the file, what is wrong, the version, the unit and the study file's
// pattern.
HumanClips loadHumanClips(const stimuli::StudyFile& study, const stimuli::StudyListing& listing, HumanProbeCache& cache,
                          const VideoProber& probe = {});

// A unit's input hash with its recordings' hashes joined (unchanged when it shows none, so
// studies without human versions keep their hashes).
std::string withHumanClips(const std::string& inputHash, const std::vector<HumanClip>& clips);

// What the manifest says a normalised clip came from.
nlohmann::json humanSource(const HumanClip& clip);

// The recording decoded to the study's size and rate (letterboxed), frame by frame.
std::unique_ptr<render::VideoFrameReader> humanFrames(const HumanClip& clip, std::uint32_t width, std::uint32_t height,
                                                      const render::FrameRate& rate);

// The frame of a normalised clip its poster shows: the middle.
std::uint64_t humanPosterFrame(const HumanClip& clip, const render::FrameRate& rate);

}  // namespace signstim::app
