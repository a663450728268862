// glTF validation: the files a model names. Reading the model file itself, decoding the URIs of
// its images and buffers as tinygltf does, and keeping them inside the model's folder
// (gltf_files.hpp).
#include "renderer/gltf_files.hpp"

#include "common/error.hpp"

#include <fstream>
#include <sstream>

namespace signstim::render::gltf_detail {
namespace fs = std::filesystem;

// Reads the file `path` whole; `file` names it in errors.
std::string readGltfFile(const fs::path& path, const std::string& file) {
    auto fail = [&](const std::string& message) { throw InputError(file, 0, "", message); };
    std::error_code ec;
    const auto status = fs::status(path, ec);
    if (ec || !fs::exists(status)) fail("file not found");
    if (fs::is_directory(status)) fail("is a directory, expected a .gltf or .glb file");
    if (!fs::is_regular_file(status)) fail("is not a regular file");
    std::ifstream in(path, std::ios::binary);
    if (!in) fail("cannot open for reading");
    std::ostringstream content;
    content << in.rdbuf();
    if (!in && !in.eof()) fail("read error");
    return content.str();
}

// The file name tinygltf will open for `uri`: it percent-decodes exactly like this
// (dlib::urldecode: "%20" and "+" are spaces), so the checks below look at the same file.
std::string decodedUri(const std::string& uri) {
    auto hex = [](char c) {
        if (c >= '0' && c <= '9') return c - '0';
        if (c >= 'a' && c <= 'f') return c - 'a' + 10;
        if (c >= 'A' && c <= 'F') return c - 'A' + 10;
        return 0;
    };
    std::string decoded;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            decoded += ' ';
        } else if (uri[i] == '%' && uri.size() > i + 2) {
            decoded += static_cast<char>((hex(uri[i + 1]) << 4) | hex(uri[i + 2]));
            i += 2;
        } else {
            decoded += uri[i];
        }
    }
    return decoded;
}

// A model names its images and buffers relative to its own folder. One that names an
// absolute path, or climbs out of that folder ("../../../../etc/passwd"), would make
// rendering a downloaded model read any file the user can read: refused, unless the file
// lies in a folder the user allowed (GltfLoadOptions::allowedDirectories). Symbolic links
// are followed before comparing, so a link out of the folder counts as leaving it.
fs::path checkInsideAllowedFolders(const std::string& name, const std::string& uri, const std::string& field,
                                   const fs::path& modelFolder, const GltfLoadOptions& options,
                                   const std::string& errorFile) {
    auto fail = [&](const std::string& f, const std::string& message) { throw InputError(errorFile, 0, f, message); };
    const fs::path relative(name);
    const std::string hint = options.allowFlag.empty()
                                 ? std::string()
                                 : " (a folder elsewhere can be allowed with " + options.allowFlag + " DIR)";
    if (relative.is_absolute() || relative.has_root_name() || relative.has_root_directory())
        fail(field, "'" + uri + "' is an absolute path; glTF files name their images and buffers relative to "
                                "the model's folder");
    std::error_code ec;
    const fs::path folder = fs::weakly_canonical(modelFolder, ec);
    const fs::path file = fs::weakly_canonical(folder / relative, ec);
    auto inside = [&](const fs::path& directory) {
        std::error_code error;
        const fs::path base = fs::weakly_canonical(fs::absolute(directory), error);
        const fs::path rest = file.lexically_relative(base);
        return !error && !rest.empty() && *rest.begin() != ".." && rest != ".";
    };
    if (ec || !inside(folder)) {
        bool allowed = false;
        for (const fs::path& directory : options.allowedDirectories) allowed = allowed || (!ec && inside(directory));
        if (!allowed)
            fail(field, "'" + uri + "' leads out of the model's folder " + folder.string() + " (to " +
                            file.string() + "): refused" + hint);
    }
    return file;
}

}  // namespace signstim::render::gltf_detail
