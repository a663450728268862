#pragma once
// Output files appear atomically: written to a temporary beside the target, then renamed.
// An interrupted run therefore never leaves a truncated file under the final name.
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

namespace signstim {

// Writes `bytes` to `path` atomically. Creates missing parent directories. Throws
// InputError naming the path when the location is not writable.
void writeFileAtomic(const std::filesystem::path& path, std::string_view bytes);

// A temporary path next to `target` (same directory, so rename() is atomic), unique per
// process and call. The caller writes it and then calls commitAtomic().
std::filesystem::path temporaryPathFor(const std::filesystem::path& target);

// Renames `temporary` onto `target`; removes `temporary` and throws on failure.
void commitAtomic(const std::filesystem::path& temporary, const std::filesystem::path& target);

// Makes sure `dir` exists and is writable (creating it if needed), else throws InputError
// naming it. Call before long work so a bad --out fails in the first second.
void ensureWritableDirectory(const std::filesystem::path& dir);

// RAII guard: removes the temporary file unless commit() was called (error paths leave
// nothing behind).
class TemporaryFile {
public:
    explicit TemporaryFile(std::filesystem::path target);
    ~TemporaryFile();
    TemporaryFile(const TemporaryFile&) = delete;
    TemporaryFile& operator=(const TemporaryFile&) = delete;

    const std::filesystem::path& path() const { return temporary_; }
    const std::filesystem::path& target() const { return target_; }
    void commit();

private:
    std::filesystem::path target_;
    std::filesystem::path temporary_;
    bool committed_ = false;
};

}  // namespace signstim
