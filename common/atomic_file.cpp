#include "common/atomic_file.hpp"

#include "common/error.hpp"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <system_error>
#include <unistd.h>

namespace signstim {
namespace fs = std::filesystem;

fs::path temporaryPathFor(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    fs::path tmp = target;
    tmp += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    return tmp;
}

void ensureWritableDirectory(const fs::path& dir) {
    if (dir.empty()) return;
    std::error_code ec;
    if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
        throw InputError(dir.string(), 0, "", "exists and is not a directory");
    fs::create_directories(dir, ec);
    if (ec)
        throw InputError(dir.string(), 0, "", "cannot create output directory: " + ec.message());
    if (::access(dir.c_str(), W_OK) != 0)
        throw InputError(dir.string(), 0, "",
                         std::string("output directory is not writable: ") + std::strerror(errno));
}

void commitAtomic(const fs::path& temporary, const fs::path& target) {
    std::error_code ec;
    fs::rename(temporary, target, ec);
    if (ec) {
        fs::remove(temporary, ec);
        throw InputError(target.string(), 0, "", "cannot write output: " + ec.message());
    }
}

void writeFileAtomic(const fs::path& path, std::string_view bytes) {
    ensureWritableDirectory(path.parent_path());
    TemporaryFile tmp(path);
    {
        std::ofstream out(tmp.path(), std::ios::binary | std::ios::trunc);
        if (!out) throw InputError(path.string(), 0, "", "cannot open for writing");
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        out.flush();
        if (!out) throw InputError(path.string(), 0, "", "write failed (disk full?)");
    }
    tmp.commit();
}

TemporaryFile::TemporaryFile(fs::path target)
    : target_(std::move(target)), temporary_(temporaryPathFor(target_)) {}

TemporaryFile::~TemporaryFile() {
    if (!committed_) {
        std::error_code ec;
        fs::remove(temporary_, ec);
    }
}

void TemporaryFile::commit() {
    commitAtomic(temporary_, target_);
    committed_ = true;
}

}  // namespace signstim
