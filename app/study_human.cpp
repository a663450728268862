#include "app/study_human.hpp"

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/number_format.hpp"
#include "common/sha256.hpp"

#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

namespace signstim::app {

using namespace signstim::stimuli;
namespace fs = std::filesystem;

namespace {

// The cache file's format; a new one when what a probe holds, or how it is judged, changes.
constexpr int kProbeCacheVersion = 1;

nlohmann::json probeJson(const render::VideoProbe& p) {
    return {{"container", p.container}, {"codec", p.codec}, {"width", p.width}, {"height", p.height},
            {"frameRate", p.frameRate}, {"durationSeconds", p.durationSeconds}, {"frames", p.frames}};
}

// A kept probe, or nothing when the entry is not one this version wrote (then it is probed again).
std::optional<render::VideoProbe> probeFromJson(const nlohmann::json& entry) {
    if (!entry.is_object() || !entry.contains("container") || !entry["container"].is_string() || !entry.contains("codec") ||
        !entry["codec"].is_string() || !entry.contains("width") || !entry["width"].is_number_unsigned() ||
        !entry.contains("height") || !entry["height"].is_number_unsigned() || !entry.contains("frameRate") ||
        !entry["frameRate"].is_string() || !entry.contains("durationSeconds") || !entry["durationSeconds"].is_number() ||
        !entry.contains("frames") || !entry["frames"].is_number_unsigned())
        return std::nullopt;
    render::VideoProbe p;
    p.container = entry["container"].get<std::string>();
    p.codec = entry["codec"].get<std::string>();
    p.width = entry["width"].get<std::uint32_t>();
    p.height = entry["height"].get<std::uint32_t>();
    p.frameRate = entry["frameRate"].get<std::string>();
    p.durationSeconds = entry["durationSeconds"].get<double>();
    p.frames = entry["frames"].get<std::uint64_t>();
    return p;
}

HumanClip probeClip(const StudyFile& study, const HumanVersion& version, std::size_t versionIndex, const std::string& unit,
                    const std::string& path, bool phase1, HumanProbeCache& cache, const VideoProber& probe) {
    HumanClip clip;
    clip.version = versionIndex;
    clip.name = version.name;
    clip.path = path;
    clip.probe = probeRecording(clip.path, clip.sha256, cache, probe);
    if (!clip.probe.problem.empty()) {
        const std::string field = "/humanVersions/" + std::to_string(version.index) + (phase1 ? "/phase1Clips" : "/phase2Clips");
        const std::string pattern = phase1 ? version.phase1Clips : version.phase2Clips;
        throw InputError(path, 0, "",
                         clip.probe.problem + ": the human version \"" + version.name + "\" of " + unit +
                             " (" + study.file + ":" + std::to_string(version.line) + ", " + field + " \"" + pattern +
                             "\"). " + (clip.probe.problem == "no such file"
                                            ? "Put the lab's recording there (docs/study.md, \"Human-video versions\")"
                                            : "Give a video ffmpeg can decode (e.g. H.264 MP4)"));
    }
    if (clip.sha256.empty()) clip.sha256 = sha256File(clip.path);
    return clip;
}

}  // namespace

HumanProbeCache readHumanProbeCache(const fs::path& studyFolder) {
    HumanProbeCache cache;
    std::ifstream in(studyFolder / kHumanProbeCacheFile, std::ios::binary);
    if (!in) return cache;
    std::ostringstream text;
    text << in.rdbuf();
    const nlohmann::json root = nlohmann::json::parse(text.str(), nullptr, false);
    if (!root.is_object() || root.value("format", "") != "signstim-human-probes" || root.value("version", 0) != kProbeCacheVersion ||
        root.value("signstim", "") != SIGNSTIM_VERSION || !root.contains("probes") || !root["probes"].is_object())
        return cache;
    for (const auto& [sha256, entry] : root["probes"].items())
        if (std::optional<render::VideoProbe> p = probeFromJson(entry)) cache.bySha256.emplace(sha256, std::move(*p));
    return cache;
}

void writeHumanProbeCache(const fs::path& studyFolder, const HumanClips& clips) {
    nlohmann::json probes = nlohmann::json::object();
    for (const auto& [unit, unitClips] : clips)
        for (const HumanClip& clip : unitClips) probes[clip.sha256] = probeJson(clip.probe);
    if (probes.empty()) return;
    const nlohmann::json root = {{"format", "signstim-human-probes"}, {"version", kProbeCacheVersion},
                                 {"signstim", SIGNSTIM_VERSION}, {"probes", std::move(probes)}};
    const std::string text = root.dump(2) + "\n";
    // Unchanged: not rewritten (a re-run touches nothing it need not).
    std::ifstream in(studyFolder / kHumanProbeCacheFile, std::ios::binary);
    std::ostringstream old;
    if (in) old << in.rdbuf();
    if (old.str() != text) writeFileAtomic(studyFolder / kHumanProbeCacheFile, text);
}

render::VideoProbe probeRecording(const fs::path& file, std::string& sha256, HumanProbeCache& cache, const VideoProber& probe) {
    sha256.clear();
    std::error_code ec;
    // Hashed only when it is a file that can be read; else the probe says what is wrong, as before.
    if (fs::is_regular_file(file, ec)) {
        try {
            sha256 = sha256File(file);
        } catch (const std::exception&) {
            sha256.clear();
        }
    }
    if (!sha256.empty())
        if (const auto kept = cache.bySha256.find(sha256); kept != cache.bySha256.end()) return kept->second;
    render::VideoProbe result = probe ? probe(file) : render::probeVideo(file);
    if (result.problem.empty() && !sha256.empty()) cache.bySha256[sha256] = result;
    return result;
}

HumanClips loadHumanClips(const StudyFile& study, const StudyListing& listing, HumanProbeCache& cache,
                          const VideoProber& probe) {
    HumanClips clips;
    const std::vector<const HumanVersion*> humans = orderedHumanVersions(study);
    const std::size_t animated = study.versions.size();
    for (std::size_t h = 0; h < humans.size(); ++h) {
        const HumanVersion& version = *humans[h];
        if (version.phase1Clips.empty()) continue;
        for (std::size_t s = 0; s < listing.stories.size(); ++s)
            clips[listing.stories[s].id].push_back(
                probeClip(study, version, animated + h, listing.stories[s].id, humanStoryClip(study, version, s), true,
                          cache, probe));
    }
    for (std::size_t i = 0; i < listing.sentences.size(); ++i) {
        // In panel order, as the side-by-side clip composes them.
        for (std::size_t v : listing.sentences[i].panelVersion) {
            if (v < animated) continue;
            const HumanVersion& version = *humans.at(v - animated);
            clips[listing.sentences[i].id].push_back(
                probeClip(study, version, v, listing.sentences[i].id, humanSentenceClip(study, version, i), false,
                          cache, probe));
        }
    }
    return clips;
}

std::string withHumanClips(const std::string& inputHash, const std::vector<HumanClip>& clips) {
    if (clips.empty()) return inputHash;
    std::string text = "signstim human clips 1\n" + inputHash + "\n";
    // The recording's bytes, not where it lives: a moved folder of recordings renders nothing again.
    for (const HumanClip& clip : clips) text += clip.name + " " + clip.sha256 + "\n";
    return sha256Hex(text);
}

nlohmann::json humanSource(const HumanClip& clip) {
    const render::VideoProbe& p = clip.probe;
    return {{"file", clip.path.filename().string()}, {"sha256", clip.sha256}, {"codec", p.codec},
            {"width", p.width}, {"height", p.height}, {"fps", p.frameRate}, {"frames", p.frames},
            {"durationSeconds", p.durationSeconds}};
}

std::unique_ptr<render::VideoFrameReader> humanFrames(const HumanClip& clip, std::uint32_t width, std::uint32_t height,
                                                      const render::FrameRate& rate) {
    return std::make_unique<render::VideoFrameReader>(clip.path, width, height, rate);
}

std::uint64_t humanPosterFrame(const HumanClip& clip, const render::FrameRate& rate) {
    return static_cast<std::uint64_t>(std::floor(0.5 * clip.probe.durationSeconds * rate.value()));
}

}  // namespace signstim::app
