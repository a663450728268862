#pragma once
// Image files (SPEC §5): PNG 8/16-bit with optional alpha, EXR and TIFF, encoded by OpenImageIO
// in memory and written atomically (common/atomic_file.hpp). The bit depth follows
// Image::format (Rgba8 -> 8-bit, Rgba16 -> 16-bit; EXR is always half float, linearised from
// the sRGB-encoded pixels).
#include "renderer/image.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace signstim::render {

struct ImageWriteOptions {
    // zlib level 0..9. Level 1 is several times faster than 6 on rendered frames for a few
    // per cent more bytes; it keeps PNG output from becoming the bottleneck.
    int pngCompression = 1;
    bool alpha = true;  // false: RGB only (alpha dropped)
};

// Format by extension: .png, .exr, .tif/.tiff. Creates missing parent directories. Encodes in
// memory, then writes through writeFileAtomic. Throws InputError naming the path (unknown
// extension, bad options) or IoError (the system refused the write: exit 3).
void writeImage(const Image& image, const std::filesystem::path& path,
                const ImageWriteOptions& options = {});

// The file contents writeImage would write to `fileName` (format by its extension).
std::vector<std::uint8_t> encodeImage(const Image& image, const std::filesystem::path& fileName,
                                      const ImageWriteOptions& options = {});

// PNG file contents in memory (for embedding, e.g. glTF images). Deterministic.
std::vector<std::uint8_t> encodePng(const Image& image, const ImageWriteOptions& options = {});

// Reads any OIIO-readable file into RGBA (missing alpha = opaque); 16-bit files give Rgba16,
// everything else Rgba8. Throws InputError naming the file.
Image readImage(const std::filesystem::path& path);

}  // namespace signstim::render
