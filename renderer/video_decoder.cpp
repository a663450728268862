#include "renderer/video_decoder.hpp"

#include "common/cleanup.hpp"
#include "common/error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace signstim::render {
namespace fs = std::filesystem;

namespace {

// sizes of what we accept [D]: H.264 levels reach 8K; a recording of a story is minutes at most.
constexpr std::uint32_t kSmallestSide = 16, kWidest = 7680, kTallest = 4320;
constexpr double kLongestSeconds = 600.0;

struct Child {
    pid_t pid = -1;
    int out = -1, err = -1;
};

// Starts `args` with stdout and stderr on pipes (stdin: /dev/null), registered for cleanup.
Child spawn(const std::vector<std::string>& args) {
    int outFds[2], errFds[2];
    if (::pipe2(outFds, O_CLOEXEC) != 0) throw EnvironmentError(std::string("pipe: ") + std::strerror(errno));
    if (::pipe2(errFds, O_CLOEXEC) != 0) {
        const int error = errno;
        ::close(outFds[0]);
        ::close(outFds[1]);
        throw EnvironmentError(std::string("pipe: ") + std::strerror(error));
    }
    std::vector<std::string> copy = args;
    std::vector<char*> argv;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, outFds[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, errFds[1], STDERR_FILENO);
    posix_spawnattr_t attributes;
    initChildSpawnAttributes(&attributes);
    Child child;
    int rc = 0;
    {
        CleanupLock lock;  // started and registered in one step (video_encoder.cpp)
        rc = posix_spawnp(&child.pid, args.front().c_str(), &actions, &attributes, argv.data(), environ);
        if (rc == 0) lock.addChild(child.pid);
    }
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    ::close(outFds[1]);
    ::close(errFds[1]);
    if (rc != 0) {
        ::close(outFds[0]);
        ::close(errFds[0]);
        if (rc == ENOENT)
            throw EnvironmentError("'" + args.front() + "' not found: reading video files needs ffmpeg and ffprobe " +
                                   "(Debian/Ubuntu: apt install ffmpeg)");
        throw EnvironmentError("cannot start '" + args.front() + "': " + std::strerror(rc));
    }
    child.out = outFds[0];
    child.err = errFds[0];
    return child;
}

std::string readAll(int fd) {
    std::string text;
    char buffer[8192];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        text.append(buffer, static_cast<std::size_t>(n));
    }
    return text;
}

std::string trimmed(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r' || text.back() == ' ')) text.pop_back();
    if (text.size() > 600) text = text.substr(0, 600) + " ...";
    for (char& c : text)
        if (c == '\n') c = ' ';
    return text;
}

double number(const nlohmann::json& object, const char* key) {
    if (!object.contains(key)) return 0.0;
    const nlohmann::json& v = object[key];
    if (v.is_number()) return v.get<double>();
    if (!v.is_string()) return 0.0;
    try {
        return std::stod(v.get<std::string>());
    } catch (const std::logic_error&) {
        return 0.0;
    }
}

}  // namespace

VideoProbe probeVideo(const fs::path& file, const std::string& ffprobe) {
    VideoProbe probe;
    std::error_code ec;
    const fs::file_status status = fs::status(file, ec);
    if (!fs::exists(status)) {
        probe.problem = "no such file";
        return probe;
    }
    if (!fs::is_regular_file(status)) {
        probe.problem = "not a file";
        return probe;
    }
    const Child child = spawn({ffprobe, "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                               "stream=codec_name,width,height,r_frame_rate,nb_read_frames,duration:format=format_name,duration",
                               "-of", "json", file.string()});
    const std::string out = readAll(child.out);
    const std::string err = readAll(child.err);
    ::close(child.out);
    ::close(child.err);
    const int status2 = waitForChild(child.pid);
    const bool exited = status2 != -1 && WIFEXITED(status2) && WEXITSTATUS(status2) == 0;
    nlohmann::json json = nlohmann::json::parse(out, nullptr, false);
    if (!exited || json.is_discarded()) {
        probe.problem = "not a video ffmpeg can read" + (err.empty() ? std::string() : " (ffprobe: " + trimmed(err) + ")");
        return probe;
    }
    if (json.contains("format") && json["format"].is_object()) {
        probe.container = json["format"].value("format_name", "");
        probe.durationSeconds = number(json["format"], "duration");
    }
    if (!json.contains("streams") || !json["streams"].is_array() || json["streams"].empty()) {
        probe.problem = probe.durationSeconds <= 0.0 ? "zero duration: it holds no video frames"
                        : "no video stream" + (probe.container.empty() ? std::string() : " (a " + probe.container + " file)");
        return probe;
    }
    const nlohmann::json& stream = json["streams"][0];
    probe.codec = stream.value("codec_name", "");
    probe.width = static_cast<std::uint32_t>(std::max(0.0, number(stream, "width")));
    probe.height = static_cast<std::uint32_t>(std::max(0.0, number(stream, "height")));
    probe.frameRate = stream.value("r_frame_rate", "");
    probe.frames = static_cast<std::uint64_t>(std::max(0.0, number(stream, "nb_read_frames")));
    if (const double d = number(stream, "duration"); d > 0.0) probe.durationSeconds = d;
    const std::string what = probe.codec.empty() ? "its video" : "its " + probe.codec + " video";
    if (!err.empty() && probe.frames == 0)
        probe.problem = what + " cannot be decoded (ffprobe: " + trimmed(err) + ")";
    else if (probe.frames == 0)
        probe.problem = what + " has no frames";
    else if (probe.durationSeconds <= 0.0)
        probe.problem = what + " has zero duration";
    else if (probe.frames == 1)
        probe.problem = what + " is a single still frame, not a video";
    else if (probe.width < kSmallestSide || probe.height < kSmallestSide || probe.width > kWidest || probe.height > kTallest)
        probe.problem = what + " is " + std::to_string(probe.width) + "x" + std::to_string(probe.height) +
                        ": expected 16x16 to 7680x4320";
    else if (probe.durationSeconds > kLongestSeconds)
        probe.problem = what + " lasts " + std::to_string(static_cast<long long>(probe.durationSeconds)) +
                        " s: expected at most 600 s (one story or sentence)";
    else if (!err.empty())
        probe.problem = what + " has frames that cannot be decoded (ffprobe: " + trimmed(err) + ")";
    return probe;
}

VideoFrameReader::VideoFrameReader(const fs::path& file, std::uint32_t width, std::uint32_t height, const FrameRate& rate,
                                   const std::string& ffmpeg)
    : file_(file), width_(width), height_(height) {
    const std::string w = std::to_string(width), h = std::to_string(height);
    const std::string flags = "bicubic+accurate_rnd+full_chroma_int+bitexact";
    // See the header: resample by timestamps, fit inside keeping the aspect, centre on black.
    const std::string filters = "fps=fps=" + rate.text() + ":round=up,scale=w=" + w + ":h=" + h +
                                ":force_original_aspect_ratio=decrease:flags=" + flags + ",pad=" + w + ":" + h +
                                ":(ow-iw)/2:(oh-ih)/2:color=black,setsar=1,format=rgba";
    const Child child = spawn({ffmpeg, "-hide_banner", "-nostdin", "-loglevel", "error", "-i", file.string(), "-map", "0:v:0",
                               "-an", "-sn", "-dn", "-vf", filters, "-sws_flags", flags, "-threads", "1", "-filter_threads",
                               "1", "-f", "rawvideo", "-pix_fmt", "rgba", "pipe:1"});
    child_ = child.pid;
    pipe_ = child.out;
    errors_ = child.err;
}

VideoFrameReader::~VideoFrameReader() { stop(); }

void VideoFrameReader::stop() noexcept {
    if (pipe_ >= 0) ::close(pipe_);
    pipe_ = -1;
    if (child_ > 0) {
        ::kill(child_, SIGTERM);
        waitForChild(child_);
        child_ = -1;
    }
    if (errors_ >= 0) ::close(errors_);
    errors_ = -1;
}

void VideoFrameReader::fail(const std::string& what) {
    std::string said;
    if (pipe_ >= 0) ::close(pipe_);
    pipe_ = -1;
    if (errors_ >= 0) said = trimmed(readAll(errors_));
    stop();
    ended_ = true;
    throw EnvironmentError("ffmpeg failed reading " + file_.string() + ": " + what +
                           (said.empty() ? std::string() : "\nffmpeg said: " + said));
}

bool VideoFrameReader::next(Image& frame) {
    if (ended_) return false;
    const std::size_t size = static_cast<std::size_t>(width_) * height_ * 4;
    frame.width = width_;
    frame.height = height_;
    frame.format = PixelFormat::Rgba8;
    frame.bytes.resize(size);
    std::size_t got = 0;
    while (got < size) {
        const ssize_t n = ::read(pipe_, frame.bytes.data() + got, size - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) fail(std::string("reading its output: ") + std::strerror(errno));
        if (n == 0) break;
        got += static_cast<std::size_t>(n);
    }
    if (got == size) {
        ++frames_;
        return true;
    }
    // The end: ffmpeg must have exited 0, said nothing, and given whole frames.
    ::close(pipe_);
    pipe_ = -1;
    const std::string said = trimmed(readAll(errors_));
    ::close(errors_);
    errors_ = -1;
    const int status = waitForChild(child_);
    child_ = -1;
    ended_ = true;
    std::string problem;
    if (status == -1 || !WIFEXITED(status) || WEXITSTATUS(status) != 0) problem = "it failed";
    else if (got != 0) problem = "its output ended inside a frame";
    else if (frames_ == 0) problem = "it gave no frames";
    else if (!said.empty()) problem = "it reported an error";
    if (!problem.empty())
        throw EnvironmentError("ffmpeg failed reading " + file_.string() + ": " + problem +
                               (said.empty() ? std::string() : "\nffmpeg said: " + said));
    return false;
}

LabelRect gridCell(std::uint32_t width, std::uint32_t height, std::uint32_t columns, std::uint32_t rows, std::size_t index) {
    const auto column = static_cast<std::uint32_t>(index % columns);
    const auto row = static_cast<std::uint32_t>(index / columns);
    LabelRect cell;
    cell.x = column * width / columns;
    cell.y = row * height / rows;
    cell.width = (column + 1) * width / columns - cell.x;
    cell.height = (row + 1) * height / rows - cell.y;
    return cell;
}

VideoCellSink::VideoCellSink(FrameSink& next, std::unique_ptr<VideoFrameReader> reader, const LabelRect& cell, std::string label)
    : next_(next), reader_(std::move(reader)), cell_(cell), label_(std::move(label)) {
    if (reader_->width() != cell.width || reader_->height() != cell.height)
        throw std::invalid_argument("VideoCellSink: the video's frames must be the cell's size");
}

bool VideoCellSink::advance() {
    if (videoEnded_) return false;
    Image next;
    if (reader_->next(next)) {
        video_ = std::move(next);
        return true;
    }
    videoEnded_ = true;
    return false;
}

void VideoCellSink::paint(Image& frame) const {
    if (frame.format != PixelFormat::Rgba8 || cell_.x + cell_.width > frame.width || cell_.y + cell_.height > frame.height)
        throw std::invalid_argument("VideoCellSink: an RGBA8 frame holding the cell is needed");
    if (video_.bytes.empty()) return;
    const std::size_t row = static_cast<std::size_t>(cell_.width) * 4;
    for (std::uint32_t y = 0; y < cell_.height; ++y)
        std::memcpy(frame.bytes.data() + ((static_cast<std::size_t>(cell_.y) + y) * frame.width + cell_.x) * 4,
                    video_.bytes.data() + static_cast<std::size_t>(y) * row, row);
    if (!label_.empty()) drawLabel(frame, cell_, label_);
}

void VideoCellSink::push(Image&& frame) {
    advance();  // after the video's last frame the cell holds it
    paint(frame);
    last_ = frame;
    ++count_;
    next_.push(std::move(frame));
}

void VideoCellSink::finish() {
    if (finished_) return;
    finished_ = true;
    // The video outlasts the other panels: they hold their last frame while it plays on.
    while (!last_.bytes.empty() && advance()) {
        Image frame = last_;
        paint(frame);
        ++count_;
        next_.push(std::move(frame));
    }
    next_.finish();
}

}  // namespace signstim::render
