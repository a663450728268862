#include "tests/app/run_command.hpp"

#include <fstream>
#include <sstream>

#include <sys/wait.h>

#include <array>
#include <cstdio>

namespace signstim::test {

CommandResult runShell(const std::string& command, Capture capture) {
    CommandResult result;
    const std::string line = command + (capture == Capture::StdoutOnly ? " 2>/dev/null" : " 2>&1");
    FILE* pipe = ::popen(line.c_str(), "r");
    if (pipe == nullptr) return result;
    std::array<char, 4096> buffer{};
    std::size_t n = 0;
    while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
    const int status = ::pclose(pipe);
    result.status = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return result;
}

CommandResult runSignstim(const std::string& arguments, Capture capture, const std::string& environment) {
    return runShell((environment.empty() ? "" : environment + " ") + shellQuote(SIGNSTIM_EXE) + " " + arguments,
                    capture);
}

CommandResult writeSyntheticRecording(const std::filesystem::path& file, const std::string& size, int rate, double seconds,
                                      int hue) {
    std::filesystem::create_directories(file.parent_path());
    return runShell("ffmpeg -v error -y -f lavfi -i 'testsrc2=size=" + size + ":rate=" + std::to_string(rate) +
                    ":duration=" + std::to_string(seconds) + ",hue=h=" + std::to_string(hue) +
                    "' -c:v libx264 -pix_fmt yuv420p " + shellQuote(file.string()) + " </dev/null");
}

std::string shellQuote(const std::string& text) {
    std::string quoted = "'";
    for (const char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

std::string readFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

std::filesystem::path freshDir(const std::filesystem::path& root, const std::string& group, const std::string& name,
                               bool create) {
    const std::filesystem::path dir = root / group / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(create ? dir : dir.parent_path());
    return dir;
}

}  // namespace signstim::test
