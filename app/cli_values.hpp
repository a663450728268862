#pragma once
// Values given on the command line as text (--size 640x480, --gaze 0,100,400, --background
// '#ffffff'): one parser each, shared by every command. Each throws
// InputError("<command line>", 0, FLAG, "expected ..., got '...'") (exit status 1: usage).
#include "common/error.hpp"
#include "signer/avatar_render.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace signstim::app {

using signstim::kCommandLine;  // the "file" of flag errors (common/error.hpp)

// InputError("<command line>", 0, flag, message), for checks of one command's own.
InputError commandLineError(const std::string& flag, const std::string& message);

struct SizeLimits {
    std::uint32_t minimum = 1;      // each side, inclusive
    std::uint32_t maximum = 16384;  // each side, inclusive
    bool even = false;              // both sides even (H.264 yuv420p panels)
};

struct ImageSize {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
};

// "WxH" (or "WXH"), decimal, nothing else: "640x480".
ImageSize parseImageSize(const std::string& text, const std::string& flag, const SizeLimits& limits = {});

// One finite decimal number ("0.5", "-3", "1e-2"; spaces around it allowed).
float parseNumber(const std::string& text, const std::string& flag);

// minCount..maxCount finite numbers separated by commas ("1,2,3"; spaces around each allowed).
std::vector<float> parseNumbers(const std::string& text, const std::string& flag, std::size_t minCount,
                                std::size_t maxCount);

// "x,y,z": three finite numbers.
glm::vec3 parseTriple(const std::string& text, const std::string& flag);

// "#rrggbb", "r,g,b[,a]" (components 0..1; r,g,b sRGB like the hex form) or "transparent"
// -> linear RGBA (alpha as given, 1 when absent; transparent is 0,0,0,0).
glm::vec4 parseColour(const std::string& text, const std::string& flag);

// `count` when it is a Vulkan sample count (1, 2, 4, 8, 16, 32 or 64); whether the chosen device
// has it is the renderer's check (lavapipe: 1 and 4), made before anything is written.
std::uint32_t requireSampleCount(std::uint32_t count, const std::string& flag);

// value itself when minimum <= value <= maximum (NaN is refused); `unit` ends the message
// ("mm" -> "expected 100 to 300 mm, got 350").
double requireInRange(double value, double minimum, double maximum, const std::string& flag,
                      const std::string& unit = "");

// The shard {I, N} of a Slurm array task, from the values of SLURM_ARRAY_TASK_ID,
// SLURM_ARRAY_TASK_COUNT and SLURM_ARRAY_TASK_MIN (null: unset; MIN defaults to 0): I = ID - MIN,
// N = COUNT. {0, 1} when ID or COUNT is unset (not an array job). Each value must be a plain
// decimal number (no sign, no space), N at most 100,000 and 0 <= I < N; anything else throws
// InputError("<environment>", 0, VARIABLE, ...) (exit status 1: the environment stands for
// --shard), never a silent shard 0.
std::pair<std::size_t, std::size_t> parseArrayTaskShard(const char* id, const char* count, const char* minimum);

// Named views of `handshapes --view`: palm, thumb, little, back, top; or "AZ,EL" in degrees.
// Throws InputError naming --view for anything else.
signer::GalleryView parseGalleryView(const std::string& text);

}  // namespace signstim::app
