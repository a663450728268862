#include "renderer/image_io.hpp"

#include "common/atomic_file.hpp"
#include "common/error.hpp"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace signstim::render {
namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

namespace {

// "png", "openexr" or "tiff" by the file's extension; InputError naming the file otherwise.
std::string formatOf(const fs::path& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".png") return "png";
    if (ext == ".exr") return "openexr";
    if (ext == ".tif" || ext == ".tiff") return "tiff";
    throw InputError(path.string(), 0, "", "unknown image extension '" + ext + "' (use .png, .exr or .tif)");
}

// The file's bytes, encoded in memory. Encoding to memory and writing the bytes through the
// one checked writer (common/atomic_file) is what makes a full disk an error: OpenImageIO's
// own file writes do not report ENOSPC reliably (a truncated PNG was written "successfully").
std::vector<std::uint8_t> encode(const Image& image, const std::string& format, const ImageWriteOptions& options) {
    const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
    if (image.width == 0 || image.height == 0 || image.bytes.size() != pixels * image.bytesPerPixel())
        throw std::invalid_argument("encodeImage: image size does not match its bytes");
    const int channels = options.alpha ? 4 : 3;
    const bool sixteen = image.format == PixelFormat::Rgba16;
    const bool exr = format == "openexr";
    const OIIO::TypeDesc fileType = exr ? OIIO::TypeDesc::HALF : sixteen ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec spec(static_cast<int>(image.width), static_cast<int>(image.height), channels, fileType);
    if (options.alpha) spec.alpha_channel = 3;
    // Our alpha is straight (not premultiplied): tell OIIO not to un-premultiply.
    spec.attribute("oiio:UnassociatedAlpha", 1);
    spec.attribute("png:compressionLevel", std::clamp(options.pngCompression, 0, 9));
    if (format == "tiff" || exr) spec.attribute("compression", "zip");

    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    const std::string name = "memory." + std::string(format == "png" ? "png" : exr ? "exr" : "tif");
    auto output = OIIO::ImageOutput::create(name, &memory);
    if (!output) throw EnvironmentError("OpenImageIO cannot write " + format + ": " + OIIO::geterror());
    bool ok = output->open(name, spec);
    if (ok && exr) {
        // EXR holds linear light: undo the sRGB encoding of the colour channels.
        std::vector<float> linear(pixels * static_cast<std::size_t>(channels));
        for (std::size_t p = 0; p < pixels; ++p)
            for (int c = 0; c < channels; ++c) {
                const float v = sixteen ? reinterpret_cast<const std::uint16_t*>(image.bytes.data())[p * 4 + c] / 65535.0f
                                        : image.bytes[p * 4 + c] / 255.0f;
                linear[p * channels + c] = c < 3 ? srgbToLinear(v) : v;
            }
        ok = output->write_image(OIIO::TypeDesc::FLOAT, linear.data());
    } else if (ok) {
        // Channels 0..channels-1 of each RGBA pixel (alpha skipped by the stride when dropped).
        ok = output->write_image(sixteen ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8, image.bytes.data(),
                                 static_cast<OIIO::stride_t>(image.bytesPerPixel()));
    }
    if (!ok || !output->close()) throw EnvironmentError(format + " encoding failed: " + output->geterror());
    return std::vector<std::uint8_t>(bytes.begin(), bytes.end());
}

}  // namespace

std::vector<std::uint8_t> encodeImage(const Image& image, const fs::path& fileName, const ImageWriteOptions& options) {
    const std::string format = formatOf(fileName);
    if (options.pngCompression < 0 || options.pngCompression > 9)
        throw InputError(fileName.string(), 0, "png-compression", "must be 0..9, got " + std::to_string(options.pngCompression));
    return encode(image, format, options);
}

void writeImage(const Image& image, const fs::path& path, const ImageWriteOptions& options) {
    const std::vector<std::uint8_t> bytes = encodeImage(image, path, options);
    writeFileAtomic(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

std::vector<std::uint8_t> encodePng(const Image& image, const ImageWriteOptions& options) {
    return encode(image, "png", options);
}

Image readImage(const fs::path& path) {
    const std::string file = path.string();
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);  // keep straight alpha as stored
    auto input = OIIO::ImageInput::open(file, &config);
    if (!input) throw InputError(file, 0, "", "cannot read image: " + OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    Image image;
    image.width = static_cast<std::uint32_t>(spec.width);
    image.height = static_cast<std::uint32_t>(spec.height);
    const bool sixteen = spec.format.size() >= 2;
    image.format = sixteen ? PixelFormat::Rgba16 : PixelFormat::Rgba8;
    const int channels = spec.nchannels;
    if (channels < 1 || spec.width < 1 || spec.height < 1) throw InputError(file, 0, "", "empty image");
    const std::size_t pixels = static_cast<std::size_t>(spec.width) * spec.height;
    const std::size_t channelBytes = sixteen ? 2 : 1;
    std::vector<std::uint8_t> raw(pixels * static_cast<std::size_t>(channels) * channelBytes);
    if (!input->read_image(0, 0, 0, channels, sixteen ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8, raw.data()))
        throw InputError(file, 0, "", "cannot read image: " + input->geterror());
    image.bytes.assign(pixels * image.bytesPerPixel(), 0);
    for (std::size_t p = 0; p < pixels; ++p) {
        for (int c = 0; c < 4; ++c) {
            // Grey: replicate; missing alpha: opaque.
            const int source = c < 3 ? (channels >= 3 ? c : 0) : (channels == 4 ? 3 : channels == 2 ? 1 : -1);
            std::uint8_t* dst = image.bytes.data() + (p * 4 + static_cast<std::size_t>(c)) * channelBytes;
            if (source < 0) std::memset(dst, 0xff, channelBytes);
            else std::memcpy(dst, raw.data() + (p * channels + static_cast<std::size_t>(source)) * channelBytes, channelBytes);
        }
    }
    return image;
}

}  // namespace signstim::render
