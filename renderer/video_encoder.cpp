#include "renderer/video_encoder.hpp"

#include "common/atomic_file.hpp"
#include "common/cleanup.hpp"
#include "common/error.hpp"

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <cstdio>
#include <mutex>
#include <numeric>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace signstim::render {
namespace fs = std::filesystem;

std::string FrameRate::text() const {
    return denominator == 1 ? std::to_string(numerator)
                            : std::to_string(numerator) + "/" + std::to_string(denominator);
}

FrameRate parseFrameRate(std::string_view text, const std::string& source, const std::string& field) {
    const std::string s(text);
    auto bad = [&](const std::string& why) -> InputError {
        return InputError(source, 0, field, "'" + s + "': " + why +
                                                " (examples: 30, 25, 30000/1001, 29.97)");
    };
    FrameRate rate;
    const std::size_t slash = s.find('/');
    try {
        std::size_t used = 0;
        if (slash != std::string::npos) {
            const unsigned long long n = std::stoull(s.substr(0, slash), &used);
            if (used != slash) throw bad("not a number");
            const std::string d = s.substr(slash + 1);
            const unsigned long long m = std::stoull(d, &used);
            if (used != d.size() || s[0] == '-' || d[0] == '-') throw bad("not a rational number");
            if (n == 0 || m == 0 || n > 1000000 || m > 1000000) throw bad("must be positive and below 10^6");
            const unsigned long long g = std::gcd(n, m);
            rate = {static_cast<std::uint32_t>(n / g), static_cast<std::uint32_t>(m / g)};
        } else {
            const double v = std::stod(s, &used);
            if (used != s.size() || !std::isfinite(v)) throw bad("not a number");
            if (v <= 0.0) throw bad("must be positive");
            // NTSC-family rates written as decimals mean the exact x*1000/1001 rational.
            for (std::uint32_t base : {24u, 30u, 48u, 60u, 120u})
                if (std::abs(v - base * 1000.0 / 1001.0) < 0.006) return {base * 1000, 1001};
            const auto milli = static_cast<unsigned long long>(std::llround(v * 1000.0));
            if (milli == 0) throw bad("must be positive");
            const unsigned long long g = std::gcd(milli, 1000ull);
            rate = {static_cast<std::uint32_t>(milli / g), static_cast<std::uint32_t>(1000 / g)};
        }
    } catch (const std::logic_error&) {  // stoull/stod: invalid_argument, out_of_range
        throw bad("not a frame rate");
    }
    if (rate.value() > 1000.0) throw bad("above 1000 fps");
    return rate;
}

namespace {

std::uint64_t bigEndian(const unsigned char* bytes, int count) {
    std::uint64_t value = 0;
    for (int i = 0; i < count; ++i) value = value << 8 | bytes[i];
    return value;
}

// Reads `fd` (ffmpeg's stderr) to its end, line by line, into `messages`; closes it.
void readMessages(int fd, VideoEncoder::Messages& messages);

// Writes all of `data` to `fd`; false on a broken pipe or other error. SIGPIPE is blocked for
// this thread meanwhile (and a pending one consumed) so a dying ffmpeg cannot kill us.
bool writeAll(int fd, const std::uint8_t* data, std::size_t size) {
    sigset_t pipeSet, previous;
    sigemptyset(&pipeSet);
    sigaddset(&pipeSet, SIGPIPE);
    pthread_sigmask(SIG_BLOCK, &pipeSet, &previous);
    bool ok = true;
    while (size > 0) {
        const ssize_t n = ::write(fd, data, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            ok = false;
            break;
        }
        data += n;
        size -= static_cast<std::size_t>(n);
    }
    if (!ok) {
        const timespec zero{0, 0};
        sigtimedwait(&pipeSet, nullptr, &zero);
    }
    pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    return ok;
}

}  // namespace

// Lines are kept as they come: error lines (the first few, which say why), the other lines
// (warnings, passed on to the user), and the last few KB (shown when the video fails).
struct VideoEncoder::Messages {
    static constexpr std::size_t kTailBytes = 4000, kMostLines = 20;
    std::mutex mutex;
    std::string tail;
    std::vector<std::string> errors, warnings;
    std::size_t warningsDropped = 0;

    void add(const std::string& line) {
        if (line.empty()) return;
        std::lock_guard lock(mutex);
        tail += line + "\n";
        if (tail.size() > kTailBytes) tail = "..." + tail.substr(tail.size() - kTailBytes);
        std::vector<std::string>& list = isFfmpegErrorLine(line) ? errors : warnings;
        if (list.size() < kMostLines) list.push_back(line);
        else if (&list == &warnings) ++warningsDropped;
    }
    std::string text() {
        std::lock_guard lock(mutex);
        std::string text = tail;
        while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
        return text;
    }
};

namespace {

void readMessages(int fd, VideoEncoder::Messages& messages) {
    std::string line;
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(fd, buffer, sizeof buffer);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;  // end: ffmpeg has exited (or the pipe failed: nothing more to read)
        for (ssize_t i = 0; i < n; ++i) {
            if (buffer[i] == '\n' || buffer[i] == '\r') {
                messages.add(line);
                line.clear();
            } else {
                line += buffer[i];
            }
        }
    }
    messages.add(line);
    ::close(fd);
}

}  // namespace

bool isFfmpegErrorLine(std::string_view line) {
    for (const std::string_view pattern : {"Error", "error", "No space left", "Invalid", "failed"})
        if (line.find(pattern) != std::string_view::npos) return true;
    return false;
}

std::string checkMp4(const fs::path& file) {
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return std::string("cannot read it: ") + std::strerror(errno);
    struct stat info{};
    std::string problem;
    if (::fstat(fd, &info) != 0) problem = std::string("cannot read it: ") + std::strerror(errno);
    const auto size = static_cast<std::uint64_t>(info.st_size);
    if (problem.empty() && size == 0) problem = "it is empty";
    bool index = false;
    for (std::uint64_t offset = 0; problem.empty() && offset < size;) {
        unsigned char header[16];
        const std::uint64_t left = size - offset;
        const ssize_t got = ::pread(fd, header, left < 16 ? static_cast<std::size_t>(left) : 16, static_cast<off_t>(offset));
        if (got < 8) {
            problem = got < 0 ? std::string("cannot read it: ") + std::strerror(errno)
                              : "it ends inside a box header (truncated)";
            break;
        }
        const std::string type(reinterpret_cast<const char*>(header) + 4, 4);
        std::uint64_t boxSize = bigEndian(header, 4), headerSize = 8;
        if (boxSize == 1) {
            if (got < 16) {
                problem = "it ends inside a box header (truncated)";
                break;
            }
            boxSize = bigEndian(header + 8, 8);
            headerSize = 16;
        } else if (boxSize == 0) {
            boxSize = left;  // "to the end of the file"
        }
        if (boxSize < headerSize) {
            problem = "box '" + type + "' has an invalid size";
            break;
        }
        if (boxSize > left) {
            problem = "box '" + type + "' runs past the end of the file (truncated)";
            break;
        }
        index = index || type == "moov";
        offset += boxSize;
    }
    ::close(fd);
    if (problem.empty() && !index) problem = "it has no 'moov' box (the index ffmpeg writes last is missing)";
    return problem;
}

VideoEncoder::VideoEncoder(fs::path output, std::uint32_t width, std::uint32_t height, PixelFormat format,
                           const VideoOptions& options)
    : output_(std::move(output)), width_(width), height_(height), format_(format) {
    const std::string file = output_.string();
    if (width == 0 || height == 0 || width % 2 != 0 || height % 2 != 0)
        throw InputError(file, 0, "size",
                         std::to_string(width) + "x" + std::to_string(height) +
                             ": MP4 output (H.264, yuv420p) needs an even width and height; choose an even --size");
    if (options.crf < 0 || options.crf > 51) throw InputError(file, 0, "crf", "must be 0..51");
    checkOutputWritable(output_);
    // ffmpeg overwrites this (-y); creating it here registers it for removal on a signal.
    temporary_ = std::make_unique<TemporaryFile>(output_);

    int fds[2], errorFds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0) throw EnvironmentError(std::string("pipe: ") + std::strerror(errno));
    if (::pipe2(errorFds, O_CLOEXEC) != 0) {
        const int error = errno;
        ::close(fds[0]);
        ::close(fds[1]);
        throw EnvironmentError(std::string("pipe: ") + std::strerror(error));
    }
    const std::string size = std::to_string(width) + "x" + std::to_string(height);
    const std::string rate = options.frameRate.text();
    // SPEC §5: H.264, yuv420p, constant frame rate, +faststart. RGB -> BT.709 limited range,
    // tagged so players convert back the same way.
    std::vector<std::string> args = {
        options.ffmpeg, "-hide_banner", "-nostdin", "-loglevel", "error", "-y",
        "-f", "rawvideo", "-pix_fmt", format == PixelFormat::Rgba16 ? "rgba64le" : "rgba",
        "-s", size, "-framerate", rate, "-i", "pipe:0", "-an",
        "-vf", "scale=out_color_matrix=bt709:out_range=tv,format=yuv420p",
        "-c:v", "libx264", "-preset", options.preset, "-crf", std::to_string(options.crf),
        "-pix_fmt", "yuv420p", "-colorspace", "bt709", "-color_primaries", "bt709", "-color_trc", "bt709",
        "-color_range", "tv", "-fps_mode", "cfr", "-r", rate, "-movflags", "+faststart"};
    if (options.threads > 0) {
        // One encoder thread count for every machine: x264's output depends on it.
        args.insert(args.end(), {"-threads", std::to_string(options.threads)});
        // ffmpeg's own filter threads do not change the bytes, but keep to the budget.
        args.insert(args.end(), {"-filter_threads", "1"});
    }
    args.insert(args.end(), {"-f", "mp4", temporary_->path().string()});
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);

    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[0], STDIN_FILENO);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, errorFds[1], STDERR_FILENO);
    posix_spawnattr_t attributes;
    initChildSpawnAttributes(&attributes);
    pid_t pid = -1;
    int rc = 0;
    {
        // Started and registered in one step: a signal either finds it registered (and ends it)
        // or comes after this program is gone.
        CleanupLock lock;
        rc = posix_spawnp(&pid, options.ffmpeg.c_str(), &actions, &attributes, argv.data(), environ);
        if (rc == 0) lock.addChild(pid);
    }
    posix_spawnattr_destroy(&attributes);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[0]);
    ::close(errorFds[1]);  // ffmpeg holds the only writing end: the reader sees the end when it exits
    if (rc != 0) {
        ::close(fds[1]);
        ::close(errorFds[0]);
        temporary_.reset();
        if (rc == ENOENT)
            throw EnvironmentError("'" + options.ffmpeg + "' not found: MP4 output needs ffmpeg with libx264 " +
                                   "(Debian/Ubuntu: apt install ffmpeg); or write PNG frames instead");
        throw EnvironmentError("cannot start '" + options.ffmpeg + "': " + std::strerror(rc));
    }
    child_ = pid;
    pipe_ = fds[1];
    messages_ = std::make_shared<Messages>();
    stderrReader_ = std::thread([fd = errorFds[0], messages = messages_] { readMessages(fd, *messages); });
    // Best effort (ffmpeg's encoder threads, started later, inherit it); failure is harmless.
    if (options.niceness > 0)
        (void)setpriority(PRIO_PROCESS, static_cast<id_t>(pid),
                          getpriority(PRIO_PROCESS, 0) + options.niceness);
}

VideoEncoder::~VideoEncoder() {
    if (!finished_) abandon();
}

void VideoEncoder::abandon() noexcept {
    if (pipe_ >= 0) {
        ::close(pipe_);
        pipe_ = -1;
    }
    if (child_ > 0) {
        ::kill(child_, SIGTERM);
        waitForChild(child_);
        child_ = -1;
    }
    joinStderrReader();
    temporary_.reset();  // removes the temporary file
}

void VideoEncoder::joinStderrReader() noexcept {
    if (stderrReader_.joinable()) stderrReader_.join();
}

void VideoEncoder::fail(const std::string& what) {
    // Let ffmpeg finish writing its complaint before reading it.
    if (pipe_ >= 0) {
        ::close(pipe_);
        pipe_ = -1;
    }
    if (child_ > 0) {
        waitForChild(child_);
        child_ = -1;
    }
    joinStderrReader();
    const std::string log = messages_ ? messages_->text() : std::string();
    abandon();
    finished_ = true;
    throw EnvironmentError("ffmpeg failed writing " + output_.string() + ": " + what +
                           (log.empty() ? std::string() : "\nffmpeg said:\n" + log));
}

void VideoEncoder::write(const Image& frame) {
    if (finished_ || pipe_ < 0) throw std::logic_error("VideoEncoder::write after finish");
    if (frame.width != width_ || frame.height != height_ || frame.format != format_ ||
        frame.bytes.size() != static_cast<std::size_t>(width_) * height_ * frame.bytesPerPixel())
        throw std::invalid_argument("VideoEncoder::write: frame size or format differs from the first frame");
    if (!writeAll(pipe_, frame.bytes.data(), frame.bytes.size())) fail("it stopped reading frames");
    ++frames_;
}

void VideoEncoder::finish() {
    if (finished_) return;
    if (frames_ == 0) fail("no frames were written");
    ::close(pipe_);
    pipe_ = -1;
    const int status = waitForChild(child_);
    child_ = -1;
    joinStderrReader();
    if (status == -1) fail("its exit status could not be read (waitpid failed)");
    if (WIFSIGNALED(status))
        fail("it was killed by signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")");
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) fail("exit status " + std::to_string(WEXITSTATUS(status)));
    // ffmpeg 5 exits 0 after "Error writing trailer of ...: No space left on device" (a
    // truncated file): its error lines fail the video, and so does a file that is not a
    // complete MP4 (in case the message was lost).
    if (!messages_->errors.empty()) fail("it reported an error");
    if (const std::string problem = checkMp4(temporary_->path()); !problem.empty())
        fail("the file it wrote is not a complete MP4: " + problem);
    // Anything else it (or a wrapper, or the dynamic loader) said is passed on, not fatal.
    for (const std::string& line : messages_->warnings)
        std::fprintf(stderr, "signstim: warning: ffmpeg (writing %s): %s\n", output_.string().c_str(), line.c_str());
    if (messages_->warningsDropped > 0)
        std::fprintf(stderr, "signstim: warning: ffmpeg (writing %s): ... and %zu more lines\n",
                     output_.string().c_str(), messages_->warningsDropped);
    finished_ = true;
    temporary_->commit();
}

}  // namespace signstim::render
