// Image files, MP4 encoding (checked with ffprobe) and frame sinks.
#include "renderer/frame_sink.hpp"
#include "renderer/image_io.hpp"
#include "renderer/video_encoder.hpp"

#include "common/error.hpp"

#include <gtest/gtest.h>

#include <array>
#include <csignal>
#include <fstream>
#include <cstdio>
#include <memory>
#include <string>

using namespace signstim;
using namespace signstim::render;
namespace fs = std::filesystem;

namespace {

fs::path testDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir = fs::path(SIGNSTIM_BINARY_DIR) / "test-tmp" / "output" /
                         (std::string(info->test_suite_name()) + "." + info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// A gradient with a moving square, so successive frames differ. Synthetic test pattern.
Image pattern(std::uint32_t width, std::uint32_t height, PixelFormat format, int frame = 0) {
    Image image;
    image.width = width;
    image.height = height;
    image.format = format;
    image.bytes.resize(static_cast<std::size_t>(width) * height * image.bytesPerPixel());
    for (std::uint32_t y = 0; y < height; ++y)
        for (std::uint32_t x = 0; x < width; ++x) {
            const bool square = x >= static_cast<std::uint32_t>(frame * 2) % width && x < static_cast<std::uint32_t>(frame * 2) % width + 8 && y < 8;
            const std::uint32_t rgba[4] = {x * 65535 / width, y * 65535 / height, square ? 65535u : 12000u,
                                           (x + y) % 3 == 0 ? 32768u : 65535u};
            const std::size_t p = static_cast<std::size_t>(y) * width + x;
            for (int c = 0; c < 4; ++c) {
                if (format == PixelFormat::Rgba8) image.bytes[p * 4 + c] = static_cast<std::uint8_t>(rgba[c] >> 8);
                else reinterpret_cast<std::uint16_t*>(image.bytes.data())[p * 4 + c] = static_cast<std::uint16_t>(rgba[c]);
            }
        }
    return image;
}

std::size_t countTemporaries(const fs::path& dir) {
    std::size_t n = 0;
    for (const auto& entry : fs::recursive_directory_iterator(dir))
        n += entry.path().filename().string().find(".tmp-") != std::string::npos;
    return n;
}

VideoOptions videoOptions(const char* rate, const char* preset = "fast", const char* ffmpeg = "ffmpeg") {
    VideoOptions options;
    options.frameRate = parseFrameRate(rate);
    options.preset = preset;
    options.ffmpeg = ffmpeg;
    return options;
}

ImageWriteOptions imageOptions(int level, bool alpha) {
    ImageWriteOptions options;
    options.pngCompression = level;
    options.alpha = alpha;
    return options;
}

std::string run(const std::string& command) {
    std::string out;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return out;
    std::array<char, 256> buffer{};
    while (std::fgets(buffer.data(), buffer.size(), pipe)) out += buffer.data();
    ::pclose(pipe);
    return out;
}

}  // namespace

TEST(ImageIo, Png8WithAlphaRoundTripsExactly) {
    const fs::path path = testDir() / "a.png";
    const Image image = pattern(37, 21, PixelFormat::Rgba8);
    writeImage(image, path);
    const Image back = readImage(path);
    EXPECT_EQ(back.width, 37u);
    EXPECT_EQ(back.format, PixelFormat::Rgba8);
    EXPECT_EQ(back.bytes, image.bytes);
    EXPECT_EQ(countTemporaries(path.parent_path()), 0u);
}

TEST(ImageIo, Png16RoundTripsExactly) {
    const fs::path path = testDir() / "b.png";
    const Image image = pattern(19, 11, PixelFormat::Rgba16);
    writeImage(image, path, imageOptions(6, true));
    const Image back = readImage(path);
    EXPECT_EQ(back.format, PixelFormat::Rgba16);
    EXPECT_EQ(back.bytes, image.bytes);
}

TEST(ImageIo, PngWithoutAlphaIsOpaque) {
    const fs::path path = testDir() / "c.png";
    const Image image = pattern(8, 8, PixelFormat::Rgba8);
    writeImage(image, path, imageOptions(1, false));
    const Image back = readImage(path);
    for (std::size_t p = 0; p < 64; ++p) {
        EXPECT_EQ(back.bytes[p * 4 + 0], image.bytes[p * 4 + 0]);
        EXPECT_EQ(back.bytes[p * 4 + 3], 255);
    }
}

TEST(ImageIo, WritesExrAndTiff) {
    const fs::path dir = testDir();
    const Image image = pattern(16, 8, PixelFormat::Rgba8);
    writeImage(image, dir / "d.exr");
    writeImage(image, dir / "d.tif");
    EXPECT_EQ(readImage(dir / "d.tif").bytes, image.bytes);
    EXPECT_EQ(readImage(dir / "d.exr").width, 16u);
    EXPECT_EQ(countTemporaries(dir), 0u);
}

TEST(ImageIo, UnwritableLocationIsAnIoErrorAndLeavesNothing) {
    const fs::path dir = testDir();
    std::ofstream(dir / "file") << "x";
    // The system refused the write (exit 3); an unknown extension is the caller's mistake.
    EXPECT_THROW(writeImage(pattern(4, 4, PixelFormat::Rgba8), dir / "file" / "x.png"), IoError);
    EXPECT_THROW(writeImage(pattern(4, 4, PixelFormat::Rgba8), dir / "x.bmpx"), InputError);
    EXPECT_EQ(countTemporaries(dir), 0u);
}

TEST(FrameRate, ParsesIntegersRationalsAndNtscDecimals) {
    EXPECT_EQ(parseFrameRate("30").text(), "30");
    EXPECT_EQ(parseFrameRate("30000/1001").text(), "30000/1001");
    EXPECT_EQ(parseFrameRate("60/2").text(), "30");
    EXPECT_EQ(parseFrameRate("29.97").text(), "30000/1001");
    EXPECT_EQ(parseFrameRate("23.976").text(), "24000/1001");
    EXPECT_EQ(parseFrameRate("12.5").text(), "25/2");
    for (const char* bad : {"", "0", "-5", "abc", "30/0", "1/2/3", "nan", "5000"})
        EXPECT_THROW(parseFrameRate(bad), InputError) << bad;
}

TEST(Video, Mp4IsH264Yuv420pWithFrameCountAndRate) {
    const fs::path path = testDir() / "v.mp4";
    {
        VideoEncoder encoder(path, 64, 48, PixelFormat::Rgba8, videoOptions("30000/1001"));
        for (int f = 0; f < 12; ++f) encoder.write(pattern(64, 48, PixelFormat::Rgba8, f));
        EXPECT_FALSE(fs::exists(path));  // appears only when complete
        encoder.finish();
    }
    ASSERT_TRUE(fs::exists(path));
    const std::string probe = run("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                                  "stream=codec_name,pix_fmt,width,height,nb_read_frames,r_frame_rate "
                                  "-of default=noprint_wrappers=1 '" + path.string() + "'");
    EXPECT_NE(probe.find("codec_name=h264"), std::string::npos) << probe;
    EXPECT_NE(probe.find("pix_fmt=yuv420p"), std::string::npos) << probe;
    EXPECT_NE(probe.find("width=64"), std::string::npos) << probe;
    EXPECT_NE(probe.find("nb_read_frames=12"), std::string::npos) << probe;
    EXPECT_NE(probe.find("r_frame_rate=30000/1001"), std::string::npos) << probe;
    EXPECT_EQ(countTemporaries(path.parent_path()), 0u);
}

TEST(Video, SixteenBitFramesEncode) {
    const fs::path path = testDir() / "v16.mp4";
    VideoEncoder encoder(path, 32, 32, PixelFormat::Rgba16);
    for (int f = 0; f < 3; ++f) encoder.write(pattern(32, 32, PixelFormat::Rgba16, f));
    encoder.finish();
    EXPECT_NE(run("ffprobe -v error -count_frames -show_entries stream=nb_read_frames -of csv=p=0 '" + path.string() + "'")
                  .find("3"),
              std::string::npos);
}

TEST(Video, OddSizeIsRefusedWithAClearMessage) {
    const fs::path dir = testDir();
    try {
        VideoEncoder encoder(dir / "odd.mp4", 65, 48, PixelFormat::Rgba8);
        ADD_FAILURE();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("even"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Video, MissingFfmpegIsAnEnvironmentError) {
    const fs::path dir = testDir();
    try {
        VideoEncoder encoder(dir / "x.mp4", 64, 48, PixelFormat::Rgba8, videoOptions("30", "fast", "ffmpeg-that-does-not-exist"));
        ADD_FAILURE();
    } catch (const EnvironmentError& e) {
        EXPECT_NE(std::string(e.what()).find("apt install ffmpeg"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Video, FfmpegFailureReportsItsStderrAndLeavesNoFile) {
    const fs::path dir = testDir();
    try {
        VideoEncoder encoder(dir / "x.mp4", 64, 48, PixelFormat::Rgba8, videoOptions("30", "no-such-preset"));
        for (int f = 0; f < 50; ++f) encoder.write(pattern(64, 48, PixelFormat::Rgba8, f));
        encoder.finish();
        ADD_FAILURE();
    } catch (const EnvironmentError& e) {
        EXPECT_NE(std::string(e.what()).find("ffmpeg said"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(Video, AbandonedEncoderLeavesNoFile) {
    const fs::path dir = testDir();
    {
        VideoEncoder encoder(dir / "x.mp4", 64, 48, PixelFormat::Rgba8);
        encoder.write(pattern(64, 48, PixelFormat::Rgba8));
    }
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(FrameSink, PngSequenceNamesFramesInOrder) {
    const fs::path dir = testDir() / "frames";
    auto sink = makeFrameSink(dir);
    for (int f = 0; f < 7; ++f) sink->push(pattern(20, 10, PixelFormat::Rgba8, f));
    sink->finish();
    EXPECT_EQ(sink->framesPushed(), 7u);
    for (int f = 0; f < 7; ++f)
        EXPECT_EQ(readImage(dir / sequenceFrameName(static_cast<std::uint64_t>(f + 1))).bytes,
                  pattern(20, 10, PixelFormat::Rgba8, f).bytes);
    EXPECT_EQ(sequenceFrameName(1), "frame_00001.png");
    EXPECT_FALSE(fs::exists(dir / "frame_00008.png"));
    EXPECT_EQ(countTemporaries(dir), 0u);
}

TEST(FrameSink, SingleImageTakesOneFrame) {
    const fs::path path = testDir() / "one.png";
    auto sink = makeFrameSink(path);
    sink->push(pattern(8, 8, PixelFormat::Rgba8));
    EXPECT_THROW(sink->push(pattern(8, 8, PixelFormat::Rgba8)), InputError);
    sink->finish();
    EXPECT_TRUE(fs::exists(path));
}

TEST(FrameSink, VideoSinkEncodesEveryFrame) {
    const fs::path path = testDir() / "s.mp4";
    auto sink = makeFrameSink(path, {}, videoOptions("25"));
    for (int f = 0; f < 20; ++f) sink->push(pattern(48, 32, PixelFormat::Rgba8, f));
    sink->finish();
    const std::string probe = run("ffprobe -v error -count_frames -show_entries stream=nb_read_frames,r_frame_rate "
                                  "-of default=noprint_wrappers=1 '" + path.string() + "'");
    EXPECT_NE(probe.find("nb_read_frames=20"), std::string::npos) << probe;
    EXPECT_NE(probe.find("r_frame_rate=25/1"), std::string::npos) << probe;
}

TEST(FrameSink, VideoErrorSurfacesOnPush) {
    const fs::path dir = testDir();
    auto sink = makeFrameSink(dir / "odd.mp4");
    EXPECT_THROW(sink->push(pattern(33, 32, PixelFormat::Rgba8)), InputError);
    sink.reset();
    EXPECT_TRUE(fs::is_empty(dir));
}

// A frame folder is written as a unit (docs/errors.md): a shorter re-render replaces the
// earlier one whole, so no stale frames of the longer render remain.
TEST(FrameSink, ShorterRerenderLeavesNoStaleFrames) {
    const fs::path dir = testDir() / "frames";
    auto first = makeFrameSink(dir);
    for (int f = 0; f < 6; ++f) first->push(pattern(20, 10, PixelFormat::Rgba8, f));
    first->finish();
    auto second = makeFrameSink(dir);
    for (int f = 0; f < 3; ++f) second->push(pattern(20, 10, PixelFormat::Rgba8, 10 + f));
    EXPECT_TRUE(fs::exists(dir / "frame_00006.png"));  // the earlier render stays until finish()
    second->finish();
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 3u);
    EXPECT_EQ(readImage(dir / "frame_00003.png").bytes, pattern(20, 10, PixelFormat::Rgba8, 12).bytes);
    EXPECT_EQ(countTemporaries(dir.parent_path()), 0u);
}

TEST(FrameSink, AbandonedFolderRenderKeepsTheEarlierOneIntact) {
    const fs::path dir = testDir() / "frames";
    auto first = makeFrameSink(dir);
    for (int f = 0; f < 4; ++f) first->push(pattern(20, 10, PixelFormat::Rgba8, f));
    first->finish();
    {
        auto second = makeFrameSink(dir);
        second->push(pattern(20, 10, PixelFormat::Rgba8, 9));
    }  // destroyed without finish(), as on an error
    EXPECT_EQ(readImage(dir / "frame_00004.png").bytes, pattern(20, 10, PixelFormat::Rgba8, 3).bytes);
    EXPECT_EQ(readImage(dir / "frame_00001.png").bytes, pattern(20, 10, PixelFormat::Rgba8, 0).bytes);
    EXPECT_EQ(countTemporaries(dir.parent_path()), 0u);
}

TEST(FrameSink, FolderHoldingOtherFilesIsRefusedBeforeRendering) {
    const fs::path dir = testDir() / "mine";
    fs::create_directories(dir);
    std::ofstream(dir / "notes.txt") << "keep me";
    try {
        makeFrameSink(dir);
        ADD_FAILURE() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_FALSE(e.isCommandLine());  // exit 2, naming the folder
        EXPECT_NE(std::string(e.what()).find("notes.txt"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("new or empty folder"), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::exists(dir / "notes.txt"));
    EXPECT_EQ(countTemporaries(dir.parent_path()), 0u);
}

TEST(FrameSink, UnknownExtensionIsACommandLineErrorAndCreatesNothing) {
    const fs::path dir = testDir();
    for (const char* name : {"a.jpg", "b.gif", "c.mov"}) {
        try {
            makeFrameSink(dir / name);
            ADD_FAILURE() << name;
        } catch (const InputError& e) {
            EXPECT_TRUE(e.isCommandLine()) << e.what();
            EXPECT_EQ(e.field(), "--out");
            EXPECT_NE(std::string(e.what()).find(".mp4"), std::string::npos) << e.what();
        }
    }
    EXPECT_TRUE(fs::is_empty(dir));
    EXPECT_EQ(outputKind("clip.MP4"), OutputKind::Video);
    EXPECT_EQ(outputKind("still.TIFF"), OutputKind::Image);
    EXPECT_EQ(outputKind("frames"), OutputKind::Folder);
    EXPECT_EQ(outputKind("out/"), OutputKind::Folder);
}

TEST(Video, FfmpegTemporariesAreRemovedOnAbandon) {
    const fs::path dir = testDir();
    {
        VideoEncoder encoder(dir / "x.mp4", 64, 48, PixelFormat::Rgba8);
        encoder.write(pattern(64, 48, PixelFormat::Rgba8));
        std::size_t temporaries = countTemporaries(dir);
        EXPECT_EQ(temporaries, 1u);  // ffmpeg's output, registered for removal on a signal
    }
    EXPECT_TRUE(fs::is_empty(dir));
}

// ---- what counts as a failed video (docs/errors.md, "ffmpeg failures") ----------------------

namespace {

// An executable shell script standing in for ffmpeg (a wrapper, or ffmpeg on a full disk).
std::string fakeFfmpeg(const fs::path& dir, const std::string& body) {
    const fs::path script = dir / "fake-ffmpeg";
    std::ofstream(script) << "#!/bin/sh\n" << body << "\n";
    fs::permissions(script, fs::perms::owner_all);
    return script.string();
}

void encodeFrames(const fs::path& file, const std::string& ffmpeg) {
    VideoOptions options = videoOptions("30", "fast", "ffmpeg");
    options.ffmpeg = ffmpeg;
    VideoEncoder encoder(file, 64, 48, PixelFormat::Rgba8, options);
    for (int f = 0; f < 10; ++f) encoder.write(pattern(64, 48, PixelFormat::Rgba8, f));
    encoder.finish();
}

std::string box(const std::string& type, std::size_t payload) {
    const std::size_t size = payload + 8;
    std::string bytes = {static_cast<char>(size >> 24), static_cast<char>(size >> 16), static_cast<char>(size >> 8),
                         static_cast<char>(size)};
    return bytes + type + std::string(payload, 'x');
}

}  // namespace

TEST(Video, CheckMp4FindsTruncatedAndIndexlessFiles) {
    const fs::path dir = testDir();
    auto check = [&](const std::string& bytes) {
        std::ofstream(dir / "f.mp4", std::ios::binary) << bytes;
        return checkMp4(dir / "f.mp4");
    };
    EXPECT_EQ(check(box("ftyp", 16) + box("moov", 40) + box("mdat", 100)), "");
    EXPECT_NE(check("").find("empty"), std::string::npos);
    EXPECT_NE(check(box("ftyp", 16) + box("free", 0) + box("mdat", 100)).find("no 'moov'"), std::string::npos);
    const std::string truncated = box("ftyp", 16) + box("moov", 40) + box("mdat", 100);
    EXPECT_NE(check(truncated.substr(0, truncated.size() - 10)).find("'mdat' runs past the end"), std::string::npos);
    EXPECT_NE(check(box("ftyp", 16) + std::string("\0\0", 2)).find("truncated"), std::string::npos);
    // A 64-bit size (size field 1) and a last box "to the end of the file" (size field 0).
    std::string large = std::string("\0\0\0\1mdat", 8) + std::string("\0\0\0\0\0\0\0\x18", 8) + "12345678";
    EXPECT_EQ(check(box("moov", 8) + large), "");
    EXPECT_EQ(check(box("moov", 8) + std::string("\0\0\0\0mdat", 8) + "abc"), "");
}

// ffmpeg 5 on a full disk: exits 0, and its "Error writing trailer" can be lost. The file
// check refuses the truncated video.
TEST(Video, TruncatedVideoFromAQuietSuccessfulFfmpegIsRefused) {
    const fs::path dir = testDir();
    const std::string ffmpeg = fakeFfmpeg(dir, "cat > /dev/null\nfor last; do :; done\n"
                                               "printf '\\000\\000\\003\\350mdat' > \"$last\"\nexit 0");
    const fs::path out = dir / "out" / "x.mp4";
    try {
        encodeFrames(out, ffmpeg);
        ADD_FAILURE() << "a truncated video was committed";
    } catch (const EnvironmentError& e) {
        EXPECT_NE(std::string(e.what()).find("not a complete MP4"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(out.string()), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fs::is_empty(out.parent_path()));
}

// An error line fails the video even when ffmpeg exits 0.
TEST(Video, ErrorLineFailsTheVideoDespiteExitZero) {
    const fs::path dir = testDir();
    const std::string ffmpeg = fakeFfmpeg(
        dir, "ffmpeg \"$@\" || exit\necho '[out#0/mp4] Error writing trailer: No space left on device' >&2\nexit 0");
    const fs::path out = dir / "out" / "x.mp4";
    try {
        encodeFrames(out, ffmpeg);
        ADD_FAILURE() << "the video was committed";
    } catch (const EnvironmentError& e) {
        EXPECT_NE(std::string(e.what()).find("ffmpeg said:\n[out#0/mp4] Error writing trailer"), std::string::npos)
            << e.what();
    }
    EXPECT_TRUE(fs::is_empty(out.parent_path()));
}

// Text that is not an ffmpeg error (a wrapper's note, the dynamic loader's complaint) is
// passed on as a warning; the video is written.
TEST(Video, OtherStderrTextIsAWarning) {
    const fs::path dir = testDir();
    const std::string ffmpeg = fakeFfmpeg(
        dir, "echo 'site wrapper: using /opt/ffmpeg' >&2\n"
             "echo \"ERROR: ld.so: object 'libx.so' from LD_PRELOAD cannot be preloaded: ignored.\" >&2\n"
             "exec ffmpeg \"$@\"");
    const fs::path out = dir / "x.mp4";
    testing::internal::CaptureStderr();
    EXPECT_NO_THROW(encodeFrames(out, ffmpeg));
    const std::string said = testing::internal::GetCapturedStderr();
    EXPECT_TRUE(fs::exists(out));
    EXPECT_NE(said.find("signstim: warning: ffmpeg (writing " + out.string() + "): site wrapper: using /opt/ffmpeg"),
              std::string::npos)
        << said;
    EXPECT_NE(said.find("cannot be preloaded"), std::string::npos) << said;
    EXPECT_FALSE(isFfmpegErrorLine("ERROR: ld.so: object 'libx.so' from LD_PRELOAD cannot be preloaded: ignored."));
    EXPECT_TRUE(isFfmpegErrorLine("av_interleaved_write_frame(): No space left on device"));
    EXPECT_TRUE(isFfmpegErrorLine("Conversion failed!"));
}

// ffmpeg runs in its own process group (Ctrl-C reaches signstim alone) with SIGPIPE at its
// default even though the signstim command ignores it (an ignored signal survives exec).
TEST(Video, FfmpegGetsItsOwnProcessGroupAndDefaultSigpipe) {
    const fs::path dir = testDir();
    const std::string ffmpeg = fakeFfmpeg(
        dir, "ignored=$(sed -n 's/^SigIgn:[[:space:]]*//p' /proc/$$/status)\n"
             "[ $(( 0x$ignored & 0x1000 )) -eq 0 ] || { echo 'Error: SIGPIPE is ignored' >&2; exit 1; }\n"
             "[ \"$(cut -d' ' -f5 /proc/$$/stat)\" = \"$$\" ] || { echo 'Error: shares a process group' >&2; exit 1; }\n"
             "exec ffmpeg \"$@\"");
    struct sigaction ignore{}, previous{};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    ::sigaction(SIGPIPE, &ignore, &previous);
    try {
        encodeFrames(dir / "x.mp4", ffmpeg);
    } catch (const std::exception& e) {
        ADD_FAILURE() << e.what();
    }
    ::sigaction(SIGPIPE, &previous, nullptr);
    EXPECT_TRUE(fs::exists(dir / "x.mp4"));
}
