#include "renderer/frame_sink.hpp"

#include "common/atomic_file.hpp"
#include "common/error.hpp"

#include <algorithm>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

namespace signstim::render {
namespace fs = std::filesystem;

std::string sequenceFrameName(std::uint64_t number) {
    char name[40];
    std::snprintf(name, sizeof name, "frame_%05llu.png", static_cast<unsigned long long>(number));
    return name;
}

namespace {

std::string lowerExtension(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

// Bounded multi-producer/multi-consumer queue with a first-error slot: workers report
// failures through it, push() and finish() rethrow them on the caller's thread.
template <typename T>
class WorkQueue {
public:
    explicit WorkQueue(std::size_t capacity) : capacity_(std::max<std::size_t>(capacity, 1)) {}

    void push(T item) {
        std::unique_lock lock(mutex_);
        notFull_.wait(lock, [&] { return queue_.size() < capacity_ || error_ || closed_; });
        rethrowLocked();
        if (closed_) throw std::logic_error("FrameSink: push after finish");
        queue_.push_back(std::move(item));
        notEmpty_.notify_one();
    }
    std::optional<T> pop() {  // empty once closed and drained (or failed)
        std::unique_lock lock(mutex_);
        notEmpty_.wait(lock, [&] { return !queue_.empty() || closed_ || error_; });
        if (error_ || queue_.empty()) return std::nullopt;
        T item = std::move(queue_.front());
        queue_.pop_front();
        notFull_.notify_one();
        return item;
    }
    void close() {
        std::lock_guard lock(mutex_);
        closed_ = true;
        notEmpty_.notify_all();
        notFull_.notify_all();
    }
    void fail(std::exception_ptr error) {
        std::lock_guard lock(mutex_);
        if (!error_) error_ = error;
        queue_.clear();
        notEmpty_.notify_all();
        notFull_.notify_all();
    }
    void rethrow() {
        std::lock_guard lock(mutex_);
        rethrowLocked();
    }

private:
    void rethrowLocked() {
        if (error_) std::rethrow_exception(error_);
    }
    std::size_t capacity_;
    std::mutex mutex_;
    std::condition_variable notFull_, notEmpty_;
    std::deque<T> queue_;
    std::exception_ptr error_;
    bool closed_ = false;
};

// Encoder threads (and ffmpeg) run this much nicer than the render thread. Where rendering
// itself runs on the CPU (lavapipe), both compete for the same cores, and at equal priority
// the encoders preempt the rasterizer threads: measured end to end was then the *sum* of the
// stages. Niced, the encoders take the cores' idle time (rendering has serial phases: vertex
// processing and binning, resolve, copy, readback), and the bounded queues still throttle
// rendering when encoding is the slower stage.
constexpr int kEncoderNiceness = 10;

void lowerThisThreadPriority() {
    // Linux: niceness is per thread (setpriority on the thread id). Best effort.
    (void)setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()),
                      getpriority(PRIO_PROCESS, static_cast<id_t>(gettid())) + kEncoderNiceness);
}

// Buffers of written frames, kept for FrameSink::recycle (at most `limit`).
class SparePool {
public:
    explicit SparePool(std::size_t limit) : limit_(limit) {}
    void give(Image&& image) {
        std::lock_guard lock(mutex_);
        if (spares_.size() < limit_) spares_.push_back(std::move(image));
    }
    bool take(Image& out) {
        std::lock_guard lock(mutex_);
        if (spares_.empty()) return false;
        out = std::move(spares_.back());
        spares_.pop_back();
        return true;
    }

private:
    std::size_t limit_;
    std::mutex mutex_;
    std::vector<Image> spares_;
};

class ImageFileSink final : public FrameSink {
public:
    ImageFileSink(fs::path file, ImageWriteOptions options) : file_(std::move(file)), options_(options) {}
    void push(Image&& frame) override {
        if (pushed_ > 0)
            throw InputError(file_.string(), 0, "", "a single image file holds one frame; use a directory or .mp4 for " +
                                                        std::string("several"));
        ++pushed_;
        frame_ = std::move(frame);
    }
    void finish() override {
        if (pushed_ == 0) throw InputError(file_.string(), 0, "", "no frame was rendered");
        if (!written_) writeImage(frame_, file_, options_);
        written_ = true;
    }
    std::uint64_t framesPushed() const override { return pushed_; }

private:
    fs::path file_;
    ImageWriteOptions options_;
    Image frame_;
    std::uint64_t pushed_ = 0;
    bool written_ = false;
};

// The folder is written as a unit (docs/errors.md): frames go into a temporary sibling folder
// that replaces `directory` only at finish(), so a failed or interrupted render leaves either
// nothing or the earlier render untouched, and a shorter re-render leaves no stale frames.
class PngSequenceSink final : public FrameSink {
public:
    PngSequenceSink(const fs::path& directory, ImageWriteOptions options, unsigned threads)
        : directory_(withoutTrailingSeparators(directory)), options_(options),
          queue_(2 * std::max(1u, threads)), spares_(2 * std::max(1u, threads) + 2),
          folder_(prepared(directory_, options_)) {
        for (unsigned t = 0; t < std::max(1u, threads); ++t) workers_.emplace_back([this] { run(); });
    }
    ~PngSequenceSink() override {
        queue_.fail(std::make_exception_ptr(std::runtime_error("abandoned")));
        join();
    }
    void push(Image&& frame) override {
        queue_.push(Job{++pushed_, std::move(frame)});
    }
    void finish() override {
        queue_.close();
        join();
        queue_.rethrow();
        folder_.commit();
    }
    std::uint64_t framesPushed() const override { return pushed_; }
    bool recycle(Image& out) override { return spares_.take(out); }

private:
    // Checks made before any frame is rendered; then the temporary folder's target.
    static fs::path prepared(const fs::path& directory, const ImageWriteOptions& options) {
        if (options.pngCompression < 0 || options.pngCompression > 9)
            throw InputError(directory.string(), 0, "png-compression",
                             "must be 0..9, got " + std::to_string(options.pngCompression));
        checkFrameFolder(directory);
        checkOutputWritable(directory);
        return directory;
    }
    struct Job {
        std::uint64_t number;
        Image image;
    };
    void run() {
        lowerThisThreadPriority();
        while (auto job = queue_.pop()) {
            try {
                const std::string name = sequenceFrameName(job->number);
                const std::vector<std::uint8_t> bytes = encodePng(job->image, options_);
                writeNewFile(folder_.path() / name,
                             std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
                             directory_ / name);
                spares_.give(std::move(job->image));
            } catch (...) {
                queue_.fail(std::current_exception());
            }
        }
    }
    void join() {
        for (std::thread& t : workers_)
            if (t.joinable()) t.join();
    }
    fs::path directory_;
    ImageWriteOptions options_;
    WorkQueue<Job> queue_;
    SparePool spares_;
    TemporaryFolder folder_;  // removed with its frames unless finish() put it in place
    std::vector<std::thread> workers_;
    std::uint64_t pushed_ = 0;
};

class VideoSink final : public FrameSink {
public:
    VideoSink(fs::path file, VideoOptions options, unsigned queueFrames)
        : file_(std::move(file)), options_(std::move(options)), queue_(queueFrames),
          spares_(std::max(1u, queueFrames) + 2) {
        if (options_.niceness == 0) options_.niceness = kEncoderNiceness;
        checkOutputWritable(file_);
    }
    ~VideoSink() override {
        queue_.fail(std::make_exception_ptr(std::runtime_error("abandoned")));
        if (worker_.joinable()) worker_.join();
        // encoder_'s destructor stops ffmpeg and removes the temporary file.
    }
    void push(Image&& frame) override {
        if (!encoder_) {
            // Started on the caller's thread so size and ffmpeg problems surface at once.
            encoder_ = std::make_unique<VideoEncoder>(file_, frame.width, frame.height, frame.format, options_);
            worker_ = std::thread([this] { run(); });
        }
        ++pushed_;
        queue_.push(std::move(frame));
    }
    void finish() override {
        queue_.close();
        if (worker_.joinable()) worker_.join();
        queue_.rethrow();
        if (!encoder_) throw InputError(file_.string(), 0, "", "no frame was rendered");
        encoder_->finish();
    }
    std::uint64_t framesPushed() const override { return pushed_; }
    bool recycle(Image& out) override { return spares_.take(out); }

private:
    void run() {
        lowerThisThreadPriority();
        while (auto frame = queue_.pop()) {
            try {
                encoder_->write(*frame);
                spares_.give(std::move(*frame));
            } catch (...) {
                queue_.fail(std::current_exception());
            }
        }
    }
    fs::path file_;
    VideoOptions options_;
    WorkQueue<Image> queue_;
    SparePool spares_;
    std::unique_ptr<VideoEncoder> encoder_;
    std::thread worker_;
    std::uint64_t pushed_ = 0;
};

class DiscardSink final : public FrameSink {
public:
    void push(Image&& frame) override {
        ++pushed_;
        spare_ = std::move(frame);
    }
    void finish() override {}
    std::uint64_t framesPushed() const override { return pushed_; }
    bool recycle(Image& out) override {
        if (spare_.bytes.empty()) return false;
        out = std::move(spare_);
        spare_ = Image{};
        return true;
    }

private:
    std::uint64_t pushed_ = 0;
    Image spare_;
};

}  // namespace

std::unique_ptr<FrameSink> makeImageFileSink(const fs::path& file, const ImageWriteOptions& options) {
    checkOutputWritable(file);
    return std::make_unique<ImageFileSink>(file, options);
}

std::unique_ptr<FrameSink> makePngSequenceSink(const fs::path& directory, const ImageWriteOptions& options,
                                               unsigned threads) {
    if (threads == 0) threads = std::clamp(std::thread::hardware_concurrency(), 1u, 4u);
    return std::make_unique<PngSequenceSink>(directory, options, threads);
}

std::unique_ptr<FrameSink> makeVideoSink(const fs::path& file, const VideoOptions& options, unsigned queueFrames) {
    return std::make_unique<VideoSink>(file, options, queueFrames);
}

std::unique_ptr<FrameSink> makeDiscardSink() { return std::make_unique<DiscardSink>(); }

std::unique_ptr<FrameSink> makeFrameSink(const fs::path& output, const ImageWriteOptions& imageOptions,
                                         const VideoOptions& videoOptions) {
    switch (outputKind(output)) {
        case OutputKind::Video: return makeVideoSink(output, videoOptions);
        case OutputKind::Image: return makeImageFileSink(output, imageOptions);
        case OutputKind::Folder: break;
    }
    return makePngSequenceSink(output, imageOptions);
}

OutputKind outputKind(const fs::path& output, const std::string& flag) {
    const fs::path name = withoutTrailingSeparators(output);
    const std::string ext = lowerExtension(name);
    // "frames/" (as tab completion writes it) is the folder "frames". "a.mp4/" asks for a file
    // and a folder at once: refused rather than guessed.
    if (name.native().size() != output.native().size()) {
        if (ext.empty()) return OutputKind::Folder;
        throw InputError(kCommandLine, 0, flag,
                         "'" + output.string() + "': a trailing '/' names a folder, but '" +
                             name.extension().string() + "' names a file; drop the '/' for a file, or choose a "
                             "folder name without an extension (frame_00001.png ...)");
    }
    if (ext == ".mp4") return OutputKind::Video;
    if (ext == ".png" || ext == ".exr" || ext == ".tif" || ext == ".tiff") return OutputKind::Image;
    if (ext.empty()) return OutputKind::Folder;
    // A folder named "a.jpg" is almost certainly not what was meant.
    throw InputError(kCommandLine, 0, flag,
                     "'" + output.string() + "': no writer for '" + output.extension().string() +
                         "' files; use .mp4 (video), .png, .exr, .tif or .tiff (one image), or a folder name "
                         "without an extension (frame_00001.png ...)");
}

void checkFrameFolder(const fs::path& folder) {
    const fs::path directory = withoutTrailingSeparators(folder);
    std::error_code ec;
    const fs::file_status status = fs::status(directory, ec);
    if (!fs::exists(status)) return;
    const std::string advice = "; choose a new or empty folder (a folder holding only an earlier render's "
                               "frame_NNNNN.png files is replaced whole)";
    if (!fs::is_directory(status))
        throw InputError(directory.string(), 0, "", "exists and is not a folder" + advice);
    for (fs::directory_iterator it(directory, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        bool frame = name.size() >= 15 && name.rfind("frame_", 0) == 0 && name.ends_with(".png") &&
                     it->is_regular_file(ec);
        for (std::size_t i = 6; frame && i + 4 < name.size(); ++i) frame = name[i] >= '0' && name[i] <= '9';
        if (!frame) throw InputError(directory.string(), 0, "", "holds '" + name + "', which is not a rendered frame" + advice);
    }
    if (ec) throw IoError(directory.string(), "cannot read", ec.message());
}

}  // namespace signstim::render
