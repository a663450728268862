#include "common/sha256.hpp"

#include "common/error.hpp"

#include <fstream>
#include <vector>

namespace signstim {

Sha256::Sha256() { sha256_init(&context_); }

void Sha256::update(const void* data, std::size_t size) {
    if (size > 0) sha256_update(&context_, size, static_cast<const std::uint8_t*>(data));
}

std::array<std::uint8_t, 32> Sha256::digest() {
    std::array<std::uint8_t, 32> out{};
    sha256_digest(&context_, SHA256_DIGEST_SIZE, out.data());
    return out;
}

std::string Sha256::hexDigest() {
    static const char* hex = "0123456789abcdef";
    std::string text;
    for (std::uint8_t b : digest()) {
        text += hex[b >> 4];
        text += hex[b & 15];
    }
    return text;
}

std::string sha256Hex(std::string_view bytes) {
    Sha256 h;
    h.update(bytes);
    return h.hexDigest();
}

std::string sha256File(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(file.string(), 0, "", "cannot read file");
    Sha256 h;
    std::vector<char> chunk(1 << 16);
    while (in) {
        in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
        h.update(chunk.data(), static_cast<std::size_t>(in.gcount()));
    }
    return h.hexDigest();
}

}  // namespace signstim
