// Reading a lab's video files (renderer/video_decoder.hpp): probing says what is wrong with a
// file that is missing, not a video, empty or a still; decoding normalises any size and rate to
// the target's (letterboxed, resampled by timestamps, the same pixels every time); a video put
// into a grid cell covers that cell only and is not cut when it outlasts the other panels.
// Every clip here is SYNTHETIC: ffmpeg's procedural test patterns (lavfi testsrc/color), or
// frames of solid colour through the project's own encoder — never a recording of a person.
#include "renderer/frame_sink.hpp"
#include "renderer/video_decoder.hpp"
#include "renderer/video_encoder.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using namespace signstim::render;
namespace fs = std::filesystem;

namespace {

fs::path dir() {
    static const fs::path d = [] {
        fs::path p = fs::path(SIGNSTIM_BINARY_DIR) / "test-output" / "video_decoder_test" /
                     ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(p);
        fs::create_directories(p);
        return p;
    }();
    return d;
}

// A synthetic clip from ffmpeg's procedural test source (no person in it).
fs::path syntheticClip(const std::string& name, const std::string& source) {
    const fs::path file = dir() / name;
    const std::string command = "ffmpeg -v error -y -f lavfi -i '" + source + "' -c:v libx264 -pix_fmt yuv420p '" +
                                file.string() + "' </dev/null";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return file;
}

// A synthetic clip through the project's encoder: `frames` frames of solid colour, the red
// channel counting up, so a decoded frame says which source frame it came from.
fs::path countingClip(const std::string& name, std::uint32_t width, std::uint32_t height, int frames, const FrameRate& rate) {
    const fs::path file = dir() / name;
    VideoOptions options;
    options.frameRate = rate;
    options.crf = 0;
    VideoEncoder encoder(file, width, height, PixelFormat::Rgba8, options);
    for (int f = 0; f < frames; ++f) {
        Image image;
        image.width = width;
        image.height = height;
        image.bytes.assign(static_cast<std::size_t>(width) * height * 4, 255);
        for (std::size_t i = 0; i < image.bytes.size(); i += 4) {
            image.bytes[i] = static_cast<std::uint8_t>(20 + 20 * f);
            image.bytes[i + 1] = 128;
            image.bytes[i + 2] = 64;
        }
        encoder.write(image);
    }
    encoder.finish();
    return file;
}

const std::uint8_t* pixel(const Image& image, std::uint32_t x, std::uint32_t y) {
    return image.bytes.data() + (static_cast<std::size_t>(y) * image.width + x) * 4;
}

class CountingSink final : public FrameSink {
public:
    void push(Image&& frame) override { frames.push_back(std::move(frame)); }
    void finish() override { finished = true; }
    std::uint64_t framesPushed() const override { return frames.size(); }
    std::vector<Image> frames;
    bool finished = false;
};

}  // namespace

TEST(VideoProbe, SaysWhatIsWrongWithAFileThatIsNotAVideo) {
    EXPECT_EQ(probeVideo(dir() / "no-such-clip.mp4").problem, "no such file");
    std::ofstream(dir() / "notes.mp4") << "these are notes, not a video\n";
    EXPECT_NE(probeVideo(dir() / "notes.mp4").problem.find("not a video"), std::string::npos) << probeVideo(dir() / "notes.mp4").problem;
    // An MP4 with no frames in it: zero duration.
    const fs::path empty = dir() / "synthetic-empty.mp4";
    const std::string command = "ffmpeg -v error -y -f lavfi -i testsrc=size=64x64:rate=10 -frames:v 0 -c:v libx264 '" +
                                empty.string() + "' </dev/null";
    ASSERT_EQ(std::system(command.c_str()), 0);
    EXPECT_NE(probeVideo(empty).problem.find("zero duration"), std::string::npos) << probeVideo(empty).problem;
    // One picture is a still, not a recording of signing.
    const fs::path still = syntheticClip("synthetic-still.mp4", "testsrc=size=64x64:rate=10:duration=0.1");
    EXPECT_NE(probeVideo(still).problem.find("single still frame"), std::string::npos) << probeVideo(still).problem;
    const fs::path tiny = syntheticClip("synthetic-tiny.mp4", "testsrc=size=8x8:rate=10:duration=1");
    EXPECT_NE(probeVideo(tiny).problem.find("expected 16x16"), std::string::npos) << probeVideo(tiny).problem;
}

TEST(VideoProbe, ReportsCodecSizeRateAndFramesOfAVideo) {
    const fs::path clip = syntheticClip("synthetic-testsrc.mp4", "testsrc2=size=96x72:rate=25:duration=2");
    const VideoProbe probe = probeVideo(clip);
    EXPECT_EQ(probe.problem, "");
    EXPECT_EQ(probe.codec, "h264");
    EXPECT_EQ(probe.width, 96u);
    EXPECT_EQ(probe.height, 72u);
    EXPECT_EQ(probe.frameRate, "25/1");
    EXPECT_EQ(probe.frames, 50u);
    EXPECT_NEAR(probe.durationSeconds, 2.0, 0.05);
}

// 4:3 at 25 fps into 64x64 at 10 fps: every frame the target's size, the picture centred with
// black above and below, as many frames as the duration holds at the new rate.
TEST(VideoFrameReader, NormalisesSizeAndRateLetterboxed) {
    const fs::path clip = syntheticClip("synthetic-43.mp4", "testsrc2=size=96x72:rate=25:duration=2");
    VideoFrameReader reader(clip, 64, 64, FrameRate{10, 1});
    Image frame;
    std::uint64_t count = 0;
    while (reader.next(frame)) {
        ++count;
        ASSERT_EQ(frame.width, 64u);
        ASSERT_EQ(frame.height, 64u);
        ASSERT_EQ(frame.bytes.size(), 64u * 64u * 4u);
        // 96x72 fits as 64x48: 8 rows of black above and below, picture in the middle.
        for (std::uint32_t x = 0; x < 64; x += 9) {
            EXPECT_LT(pixel(frame, x, 2)[0] + pixel(frame, x, 2)[1] + pixel(frame, x, 2)[2], 6);
            EXPECT_LT(pixel(frame, x, 61)[0] + pixel(frame, x, 61)[1] + pixel(frame, x, 61)[2], 6);
        }
        int lit = 0;
        for (std::uint32_t x = 0; x < 64; ++x) lit += pixel(frame, x, 32)[0] + pixel(frame, x, 32)[1] + pixel(frame, x, 32)[2];
        EXPECT_GT(lit, 64 * 60);
    }
    EXPECT_EQ(count, 20u);  // 2 s at 10 fps
}

// Output frame n shows the source frame showing at n/rate: 5 fps counted frames read at 10 fps
// repeat each, read at 2.5 fps keep every other one; the same pixels on a second read.
TEST(VideoFrameReader, ResamplesByTimestampsDeterministically) {
    const fs::path clip = countingClip("synthetic-counting.mp4", 32, 32, 6, FrameRate{5, 1});
    const auto reds = [&](const FrameRate& rate) {
        VideoFrameReader reader(clip, 32, 32, rate);
        std::vector<int> red;
        Image frame;
        while (reader.next(frame)) red.push_back((pixel(frame, 16, 16)[0] + 10) / 20);  // back to the frame number + 1
        return red;
    };
    EXPECT_EQ(reds(FrameRate{10, 1}), (std::vector<int>{1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6}));
    EXPECT_EQ(reds(FrameRate{5, 2}), (std::vector<int>{1, 3, 5}));
    // At 4 fps the instants 0, 0.25, 0.5, 0.75, 1 s show source frames 1, 2, 3, 4, 6 (at 0, 0.2,
    // 0.4, 0.6, 1.0 s): the frame showing at n/rate, not the one nearest the middle of the interval.
    EXPECT_EQ(reds(FrameRate{4, 1}), (std::vector<int>{1, 2, 3, 4, 6}));
    const auto bytes = [&] {
        VideoFrameReader reader(clip, 20, 14, FrameRate{30000, 1001});
        std::string all;
        Image frame;
        while (reader.next(frame)) all.append(frame.bytes.begin(), frame.bytes.end());
        return all;
    };
    EXPECT_EQ(bytes(), bytes());
}

// A video in panel B of a 2x2 grid: the other cells untouched, B holding the video; when the
// video is longer than the frames pushed, finish() adds frames until it ends.
TEST(VideoCellSink, PutsTheVideoInItsCellAndPlaysItToTheEnd) {
    const fs::path clip = countingClip("synthetic-panel.mp4", 32, 32, 6, FrameRate{2, 1});  // 3 s
    const LabelRect cell = gridCell(64, 64, 2, 2, 1);
    EXPECT_EQ(cell.x, 32u);
    EXPECT_EQ(cell.y, 0u);
    CountingSink out;
    VideoCellSink sink(out, std::make_unique<VideoFrameReader>(clip, cell.width, cell.height, FrameRate{2, 1}), cell, "B");
    for (int f = 0; f < 2; ++f) {
        Image grey;
        grey.width = grey.height = 64;
        grey.bytes.assign(64u * 64u * 4u, 90);
        sink.push(std::move(grey));
    }
    sink.finish();
    EXPECT_TRUE(out.finished);
    ASSERT_EQ(out.frames.size(), 6u);  // 2 pushed, 4 more for the rest of the video
    EXPECT_EQ(sink.framesPushed(), 6u);
    for (std::size_t f = 0; f < out.frames.size(); ++f) {
        const Image& image = out.frames[f];
        EXPECT_EQ(pixel(image, 10, 40)[0], 90);  // panel C: as pushed (the last pushed frame held)
        EXPECT_EQ(pixel(image, 40, 40)[1], 90);  // panel D
        EXPECT_EQ((pixel(image, 56, 24)[0] + 10) / 20, static_cast<int>(f) + 1) << f;  // panel B: video frame f
    }
}
