#include "common/standard_output.hpp"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <unistd.h>

namespace signstim {
namespace {

std::atomic<int> firstError{0};

void record(int error) {
    int expected = 0;
    firstError.compare_exchange_strong(expected, error != 0 ? error : EIO);
}

}  // namespace

void writeStandardOutput(std::string_view text) {
    errno = 0;
    if (std::fflush(stdout) != 0) record(errno);
    const char* data = text.data();
    std::size_t left = text.size();
    while (left > 0) {
        const ssize_t n = ::write(STDOUT_FILENO, data, left);
        if (n < 0) {
            if (errno == EINTR) continue;
            record(errno);
            return;
        }
        data += n;
        left -= static_cast<std::size_t>(n);
    }
}

int standardOutputError() { return firstError.load(); }

int flushStandardOutput() {
    errno = 0;
    if (std::fflush(stdout) != 0) record(errno);
    if (std::ferror(stdout)) record(errno);  // an earlier printf's write failed: EIO if its reason is lost
    errno = 0;
    if (std::fclose(stdout) != 0) record(errno);
    return standardOutputError();
}

}  // namespace signstim
