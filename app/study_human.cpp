#include "app/study_human.hpp"

#include "common/error.hpp"
#include "common/number_format.hpp"
#include "common/sha256.hpp"

#include <cmath>

namespace signstim::app {

using namespace signstim::stimuli;
namespace fs = std::filesystem;

namespace {

HumanClip probeClip(const StudyFile& study, const HumanVersion& version, std::size_t versionIndex, const std::string& unit,
                    const std::string& path, bool phase1) {
    HumanClip clip;
    clip.version = versionIndex;
    clip.name = version.name;
    clip.path = path;
    clip.probe = render::probeVideo(clip.path);
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
    clip.sha256 = sha256File(clip.path);
    return clip;
}

}  // namespace

HumanClips loadHumanClips(const StudyFile& study, const StudyListing& listing) {
    HumanClips clips;
    const std::vector<const HumanVersion*> humans = orderedHumanVersions(study);
    const std::size_t animated = study.versions.size();
    for (std::size_t h = 0; h < humans.size(); ++h) {
        const HumanVersion& version = *humans[h];
        if (version.phase1Clips.empty()) continue;
        for (std::size_t s = 0; s < listing.stories.size(); ++s)
            clips[listing.stories[s].id].push_back(
                probeClip(study, version, animated + h, listing.stories[s].id, humanStoryClip(study, version, s), true));
    }
    for (std::size_t i = 0; i < listing.sentences.size(); ++i) {
        // In panel order, as the side-by-side clip composes them.
        for (std::size_t v : listing.sentences[i].panelVersion) {
            if (v < animated) continue;
            const HumanVersion& version = *humans.at(v - animated);
            clips[listing.sentences[i].id].push_back(
                probeClip(study, version, v, listing.sentences[i].id, humanSentenceClip(study, version, i), false));
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
