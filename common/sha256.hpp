#pragma once
// SHA-256 (FIPS 180-4), for manifests: every output file is listed with its digest so a
// reviewer can check that a stimulus set is the one that was generated. The hashing is
// Nettle's (Debian's nettle-dev, the GnuTLS project's low-level crypto library), not ours.
#include <nettle/sha2.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace signstim {

class Sha256 {
public:
    Sha256();
    void update(const void* data, std::size_t size);
    void update(std::string_view text) { update(text.data(), text.size()); }
    std::array<std::uint8_t, 32> digest();  // finishes; the object must not be updated after
    std::string hexDigest();

private:
    sha256_ctx context_;
};

std::string sha256Hex(std::string_view bytes);
// Throws InputError naming the file when it cannot be read.
std::string sha256File(const std::filesystem::path& file);

}  // namespace signstim
