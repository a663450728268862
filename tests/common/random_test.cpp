#include "common/random.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

using namespace signstim;

TEST(SplitMix64, MatchesReferenceSequence) {
    // Reference values of SplitMix64 seeded with 0 (Vigna's splitmix64.c).
    SplitMix64 g(0);
    EXPECT_EQ(g.next(), 0xE220A8397B1DCDAFull);
    EXPECT_EQ(g.next(), 0x6E789E6AA1B965F4ull);
    EXPECT_EQ(g.next(), 0x06C45D188009454Full);
}

TEST(SplitMix64, BoundedDrawsStayInRangeAndCoverIt) {
    SplitMix64 g(42);
    std::vector<int> counts(7, 0);
    for (int i = 0; i < 70000; ++i) {
        const auto v = g.below(7);
        ASSERT_LT(v, 7u);
        ++counts[v];
    }
    for (int c : counts) EXPECT_NEAR(c, 10000, 500);
}

TEST(SplitMix64, NormalHasUnitMoments) {
    SplitMix64 g(7);
    double sum = 0, sumSq = 0;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
        const double x = g.normal();
        sum += x;
        sumSq += x * x;
    }
    EXPECT_NEAR(sum / n, 0.0, 0.01);
    EXPECT_NEAR(sumSq / n, 1.0, 0.02);
}

TEST(Shuffle, IsAPermutationAndDependsOnlyOnSeed) {
    std::vector<int> a(12), b(12);
    std::iota(a.begin(), a.end(), 0);
    std::iota(b.begin(), b.end(), 0);
    SplitMix64 ga(mixSeed(1, 2)), gb(mixSeed(1, 2));
    shuffleInPlace(a, ga);
    shuffleInPlace(b, gb);
    EXPECT_EQ(a, b);
    std::vector<int> sorted = a;
    std::sort(sorted.begin(), sorted.end());
    for (int i = 0; i < 12; ++i) EXPECT_EQ(sorted[i], i);
    std::vector<int> identity(12);
    std::iota(identity.begin(), identity.end(), 0);
    EXPECT_NE(a, identity);
}

TEST(Shuffle, EveryPositionReachableUniformly) {
    // Each element lands in each slot about equally often over many seeds.
    const int n = 4, trials = 40000;
    std::vector<std::vector<int>> hits(n, std::vector<int>(n, 0));
    for (int t = 0; t < trials; ++t) {
        std::vector<int> v{0, 1, 2, 3};
        SplitMix64 g(mixSeed(99, static_cast<std::uint64_t>(t)));
        shuffleInPlace(v, g);
        for (int slot = 0; slot < n; ++slot) ++hits[v[slot]][slot];
    }
    for (auto& row : hits)
        for (int c : row) EXPECT_NEAR(c, trials / n, 400);
}
