// The probes of a study's recordings kept between runs (app/study_human.hpp): a recording is
// probed (ffprobe decodes every frame) once per content, not on every load of the study; a
// changed one is probed again. The "recordings" are SYNTHETIC: a few bytes of text, probed by
// a stand-in that counts its calls and never runs ffprobe.
#include "app/study_human.hpp"

#include "common/sha256.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace {

namespace fs = std::filesystem;
using signstim::app::HumanClip;
using signstim::app::HumanClips;
using signstim::app::HumanProbeCache;
using signstim::app::kHumanProbeCacheFile;
using signstim::app::probeRecording;
using signstim::app::readHumanProbeCache;
using signstim::app::VideoProber;
using signstim::app::writeHumanProbeCache;
using signstim::render::VideoProbe;

fs::path freshDir(const std::string& name) {
    const fs::path dir = fs::path(SIGNSTIM_BINARY_DIR) / "study_human_probe_cache_test" / name;
    fs::remove_all(dir);
    fs::create_directories(dir / ".signstim");
    return dir;
}

void write(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

// A stand-in for ffprobe: what a 1.52 s clip of 96x72 at 25 fps probes as, its frame count
// taken from the file's size so that two different files probe differently.
struct CountingProber {
    int calls = 0;
    VideoProber prober() {
        return [this](const fs::path& file) {
            ++calls;
            VideoProbe p;
            p.container = "mov,mp4,m4a,3gp,3g2,mj2";
            p.codec = "h264";
            p.width = 96;
            p.height = 72;
            p.frameRate = "25/1";
            p.durationSeconds = 1.52;
            p.frames = 30 + fs::file_size(file);
            return p;
        };
    }
};

// A stand-in for ffprobe that finds `problem` in every file it is given.
VideoProber failingProber(int& calls, const std::string& problem) {
    return [&calls, problem](const fs::path&) {
        ++calls;
        VideoProbe p;
        p.problem = problem;
        return p;
    };
}

HumanClips clipsOf(const fs::path& file, const std::string& sha256, const VideoProbe& probe) {
    HumanClips clips;
    HumanClip clip;
    clip.name = "human";
    clip.path = file;
    clip.sha256 = sha256;
    clip.probe = probe;
    clips["story-01"].push_back(clip);
    return clips;
}

// A run of its own: `recording` (written with "synthetic recording A") probed by `counter` and
// its probe kept in `dir`. Its hash.
std::string probedInto(const fs::path& dir, const fs::path& recording, CountingProber& counter) {
    write(recording, "synthetic recording A\n");
    HumanProbeCache cache;
    std::string sha256;
    const VideoProbe probe = probeRecording(recording, sha256, cache, counter.prober());
    writeHumanProbeCache(dir, clipsOf(recording, sha256, probe));
    return sha256;
}

void expectSameProbe(const VideoProbe& a, const VideoProbe& b) {
    EXPECT_EQ(a.problem, b.problem);
    EXPECT_EQ(a.container, b.container);
    EXPECT_EQ(a.codec, b.codec);
    EXPECT_EQ(a.width, b.width);
    EXPECT_EQ(a.height, b.height);
    EXPECT_EQ(a.frameRate, b.frameRate);
    EXPECT_EQ(a.durationSeconds, b.durationSeconds);  // bit for bit: the manifest prints it
    EXPECT_EQ(a.frames, b.frames);
}

TEST(HumanProbeCache, ARecordingIsProbedOnceThenReadFromTheStudyFolderByTheNextRun) {
    const fs::path dir = freshDir("again");
    const fs::path recording = dir / "synthetic-story-01.mp4";
    write(recording, "synthetic recording A\n");
    CountingProber counter;

    HumanProbeCache cache = readHumanProbeCache(dir);  // no file yet: empty
    EXPECT_TRUE(cache.bySha256.empty());
    std::string sha256;
    const VideoProbe first = probeRecording(recording, sha256, cache, counter.prober());
    EXPECT_EQ(counter.calls, 1);
    EXPECT_EQ(sha256, signstim::sha256File(recording));
    probeRecording(recording, sha256, cache, counter.prober());  // the same run, the same file
    EXPECT_EQ(counter.calls, 1);

    writeHumanProbeCache(dir, clipsOf(recording, sha256, first));
    ASSERT_TRUE(fs::is_regular_file(dir / kHumanProbeCacheFile));
    HumanProbeCache next = readHumanProbeCache(dir);  // a re-run, or a shard in the same folder
    std::string again;
    const VideoProbe kept = probeRecording(recording, again, next, counter.prober());
    EXPECT_EQ(counter.calls, 1) << "the next run probed the unchanged recording again";
    EXPECT_EQ(again, sha256);
    expectSameProbe(kept, first);
}

TEST(HumanProbeCache, AChangedRecordingIsProbedAgainAndItsOldEntryDropped) {
    const fs::path dir = freshDir("changed");
    const fs::path recording = dir / "synthetic-story-01.mp4";
    CountingProber counter;
    const std::string before = probedInto(dir, recording, counter);
    ASSERT_EQ(counter.calls, 1);

    // The same size, name and folder, other bytes: only its hash tells.
    write(recording, "synthetic recording B\n");
    HumanProbeCache next = readHumanProbeCache(dir);
    std::string after;
    const VideoProbe probe = probeRecording(recording, after, next, counter.prober());
    EXPECT_EQ(counter.calls, 2) << "a changed recording was taken from the cache";
    EXPECT_NE(after, before);
    writeHumanProbeCache(dir, clipsOf(recording, after, probe));
    const HumanProbeCache written = readHumanProbeCache(dir);
    EXPECT_EQ(written.bySha256.size(), 1u);
    EXPECT_EQ(written.bySha256.count(after), 1u);
}

TEST(HumanProbeCache, AProbeThatFoundAProblemIsNotKept) {
    const fs::path dir = freshDir("problem");
    const fs::path recording = dir / "synthetic-notes.mp4";
    write(recording, "not a video\n");
    int calls = 0;
    const VideoProber broken = failingProber(calls, "not a video ffmpeg can read");
    HumanProbeCache cache;
    std::string sha256;
    EXPECT_EQ(probeRecording(recording, sha256, cache, broken).problem, "not a video ffmpeg can read");
    EXPECT_EQ(probeRecording(recording, sha256, cache, broken).problem, "not a video ffmpeg can read");
    EXPECT_EQ(calls, 2);
    EXPECT_TRUE(cache.bySha256.empty());
}

TEST(HumanProbeCache, AMissingRecordingIsLeftToTheProbeToReport) {
    const fs::path dir = freshDir("missing");
    int calls = 0;
    const VideoProber missing = failingProber(calls, "no such file");
    HumanProbeCache cache;
    std::string sha256 = "left from before";
    EXPECT_EQ(probeRecording(dir / "no-such-recording.mp4", sha256, cache, missing).problem, "no such file");
    EXPECT_EQ(calls, 1);
    EXPECT_TRUE(sha256.empty());
    EXPECT_TRUE(cache.bySha256.empty());
}

TEST(HumanProbeCache, ACacheFileThatIsNotOneIsEmpty) {
    const fs::path dir = freshDir("malformed");
    const fs::path recording = dir / "synthetic-story-01.mp4";
    CountingProber counter;
    probedInto(dir, recording, counter);
    ASSERT_EQ(readHumanProbeCache(dir).bySha256.size(), 1u);  // the file as written is read back
    const std::string good = [&] {
        std::ifstream in(dir / kHumanProbeCacheFile, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    }();
    const auto replaced = [&](const std::string& from, const std::string& to) {
        std::string text = good;
        const std::size_t at = text.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        if (at != std::string::npos) text.replace(at, from.size(), to);
        return text;
    };
    for (const std::string& bad : {std::string("{ not json"), replaced("\"version\": 1", "\"version\": 0"),
                                   replaced("\"signstim-human-probes\"", "\"signstim-plan\""),
                                   replaced("\"frames\": ", "\"frames\": -")}) {
        write(dir / kHumanProbeCacheFile, bad);
        EXPECT_TRUE(readHumanProbeCache(dir).bySha256.empty()) << bad;
    }
}

}  // namespace
