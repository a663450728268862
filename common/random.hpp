#pragma once
// Portable, seedable randomness. Same seed -> same numbers with any compiler and standard
// library (SPEC §4.2: never the standard library's shuffle or distribution classes, whose
// algorithms differ between implementations).
#include <cmath>
#include <cstdint>
#include <string_view>
#include <utility>
#include <vector>

namespace signstim {

// SplitMix64 (Steele, Lea & Flood 2014).
class SplitMix64 {
public:
    explicit constexpr SplitMix64(std::uint64_t seed) : state_(seed) {}

    constexpr std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }

    // Uniform integer in [0, bound) without modulo bias (Lemire's method with rejection).
    std::uint64_t below(std::uint64_t bound) {
        if (bound == 0) return 0;
        for (;;) {
            __uint128_t m = static_cast<__uint128_t>(next()) * bound;
            std::uint64_t low = static_cast<std::uint64_t>(m);
            if (low >= bound || low >= (-bound) % bound) return static_cast<std::uint64_t>(m >> 64);
        }
    }

    // Uniform double in [0, 1) with 53 random bits.
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

    // Standard normal by Box–Muller (both values used in turn).
    double normal() {
        if (hasSpare_) {
            hasSpare_ = false;
            return spare_;
        }
        double u1 = 0.0;
        do u1 = uniform(); while (u1 <= 0.0);
        const double u2 = uniform();
        const double radius = std::sqrt(-2.0 * std::log(u1));
        const double angle = 6.283185307179586476925 * u2;
        spare_ = radius * std::sin(angle);
        hasSpare_ = true;
        return radius * std::cos(angle);
    }

private:
    std::uint64_t state_;
    double spare_ = 0.0;
    bool hasSpare_ = false;
};

// Mixes several values into one seed (order matters).
constexpr std::uint64_t mixSeed(std::uint64_t a, std::uint64_t b) {
    SplitMix64 g(a ^ (b + 0x9E3779B97F4A7C15ull + (a << 6) + (a >> 2)));
    return g.next();
}

// FNV-1a of a string, for seeding from names.
constexpr std::uint64_t hashString(std::string_view text) {
    std::uint64_t h = 0xcbf29ce484222325ull;
    for (char c : text) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001b3ull;
    }
    return h;
}

// Fisher–Yates shuffle with the portable generator.
template <class T>
void shuffleInPlace(std::vector<T>& items, SplitMix64& rng) {
    for (std::size_t i = items.size(); i > 1; --i) {
        const std::size_t j = static_cast<std::size_t>(rng.below(i));
        std::swap(items[i - 1], items[j]);
    }
}

}  // namespace signstim
