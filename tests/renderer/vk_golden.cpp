#include "tests/renderer/vk_golden.hpp"

#include <OpenImageIO/imagebuf.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

namespace signstim::render::testing {

namespace {

constexpr int kPixelThreshold = 3;  // of 255
constexpr int kHardThreshold = 64;
constexpr double kFailFraction = 0.005;

OIIO::ImageBuf toImageBuf(const Image& image) {
    OIIO::ImageSpec spec(static_cast<int>(image.width), static_cast<int>(image.height), 4,
                         image.format == PixelFormat::Rgba8 ? OIIO::TypeDesc::UINT8
                                                            : OIIO::TypeDesc::UINT16);
    OIIO::ImageBuf buffer(spec);
    buffer.set_pixels(OIIO::ROI::All(), spec.format, image.bytes.data());
    return buffer;
}

}  // namespace

void writePng(const Image& image, const std::string& path) {
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    OIIO::ImageBuf buffer = toImageBuf(image);
    if (!buffer.write(path)) throw std::runtime_error("cannot write " + path + ": " + buffer.geterror());
}

std::string compareWithGolden(const Image& image, const std::string& name) {
    // Built with append, not `std::string(...) + "..."`: gcc 12 at -O2 warns on that form
    // (-Warray-bounds, a false positive of its inlined std::string moves) when the tests'
    // precompiled header is used (tests/CMakeLists.txt, SIGNSTIM_TEST_PCH).
    std::string goldenPath = SIGNSTIM_SOURCE_DIR;
    goldenPath.append("/tests/renderer/golden/").append(name).append(".png");
    std::string outDir = SIGNSTIM_BINARY_DIR;
    outDir.append("/tests/renderer/golden-out/");
    const char* update = std::getenv("SIGNSTIM_UPDATE_GOLDEN");
    if (update != nullptr && std::strcmp(update, "1") == 0) {
        writePng(image, goldenPath);
        return {};
    }
    const std::string actualPath = outDir + name + ".actual.png";
    const std::string diffPath = outDir + name + ".diff.png";
    if (!std::filesystem::exists(goldenPath)) {
        writePng(image, actualPath);
        return "no golden image " + goldenPath + " (actual: " + actualPath +
               "); create it with SIGNSTIM_UPDATE_GOLDEN=1";
    }
    OIIO::ImageBuf golden(goldenPath);
    if (!golden.read(0, 0, true, OIIO::TypeDesc::UINT8))
        return "cannot read " + goldenPath + ": " + golden.geterror();
    const auto& spec = golden.spec();
    if (spec.width != static_cast<int>(image.width) ||
        spec.height != static_cast<int>(image.height) || spec.nchannels != 4) {
        writePng(image, actualPath);
        return "golden " + goldenPath + " has another size or channel count (actual: " +
               actualPath + ")";
    }
    std::vector<std::uint8_t> goldenPixels(std::size_t(image.width) * image.height * 4);
    golden.get_pixels(OIIO::ROI::All(), OIIO::TypeDesc::UINT8, goldenPixels.data());
    // Exact first: same driver, same bytes.
    if (image.format == PixelFormat::Rgba8 && goldenPixels == image.bytes) return {};
    // The tolerance, counted here: OIIO's compare() flags `error` whenever any pixel is over
    // its fail threshold, which would make the allowed fraction unreachable.
    const auto actualByte = [&](std::size_t i) {
        return image.format == PixelFormat::Rgba8 ? int(image.bytes[i])
                                                  : (int(reinterpret_cast<const std::uint16_t*>(image.bytes.data())[i]) * 255 + 32767) / 65535;
    };
    std::size_t failing = 0;
    int largest = 0;
    for (std::size_t i = 0; i < goldenPixels.size(); i += 4) {
        int pixelLargest = 0;
        for (std::size_t c = 0; c < 4; ++c) pixelLargest = std::max(pixelLargest, std::abs(actualByte(i + c) - int(goldenPixels[i + c])));
        largest = std::max(largest, pixelLargest);
        if (pixelLargest > kPixelThreshold) ++failing;
    }
    const double pixels = double(image.width) * image.height;
    if (double(failing) <= kFailFraction * pixels && largest <= kHardThreshold) return {};
    writePng(image, actualPath);
    // Difference image: |actual - golden| x 8 per colour channel (alpha differences shown
    // as grey), opaque so any viewer shows it.
    Image diff;
    diff.width = image.width;
    diff.height = image.height;
    diff.bytes.resize(goldenPixels.size());
    for (std::size_t i = 0; i < goldenPixels.size(); i += 4) {
        int alphaDelta = 0;
        for (std::size_t c = 0; c < 4; ++c) {
            const int a = image.format == PixelFormat::Rgba8
                              ? image.bytes[i + c]
                              : reinterpret_cast<const std::uint16_t*>(image.bytes.data())[i + c] >> 8;
            const int delta = std::min(255, 8 * std::abs(a - int(goldenPixels[i + c])));
            if (c == 3) alphaDelta = delta; else diff.bytes[i + c] = static_cast<std::uint8_t>(delta);
        }
        for (std::size_t c = 0; c < 3; ++c)
            diff.bytes[i + c] = std::max(diff.bytes[i + c], static_cast<std::uint8_t>(alphaDelta));
        diff.bytes[i + 3] = 255;
    }
    writePng(diff, diffPath);
    std::ostringstream message;
    message << name << ": " << failing << " of " << pixels << " pixels differ by more than " << kPixelThreshold
            << "/255 (allowed " << kFailFraction * 100 << " %), max difference " << largest << "/255 (allowed "
            << kHardThreshold << "); actual: " << actualPath << ", diff (x8): " << diffPath;
    return message.str();
}

}  // namespace signstim::render::testing
