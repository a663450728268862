// The rank statistics against published and independently computed values.
// Reference values: R's documentation examples (Hollander & Wolfe 1973, "Nonparametric
// Statistical Methods", pp. 69 and 116: R prints kruskal.test chi-squared = 0.77143, df = 2,
// p-value = 0.68, and wilcox.test(x, y, alternative = "g") W = 35, p-value = 0.1272), SciPy's
// documentation examples (scipy.stats.kruskal and mannwhitneyu), and further values computed
// with SciPy 1.10.1 (Debian bookworm's python3-scipy: scipy.stats.kruskal, mannwhitneyu with
// method="exact" / "asymptotic", use_continuity=True) — listed with each test, to 1e-10.
#include "analysis/rank_tests.hpp"

#include "common/random.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace signstim::analysis;

TEST(RankTests, MidranksAverageTiedPositions) {
    const std::vector<double> ranks = midranks({10, 20, 20, 5, 20, 30});
    EXPECT_EQ(ranks, (std::vector<double>{2, 4, 4, 1, 4, 6}));
    EXPECT_DOUBLE_EQ(tieTerm({10, 20, 20, 5, 20, 30}), 24.0);  // one group of 3: 27 - 3
}

TEST(RankTests, KruskalWallisMatchesHollanderWolfeMucociliaryExample) {
    // Hollander & Wolfe (1973) p. 116; R: chi-squared = 0.77143, df = 2, p-value = 0.68.
    // SciPy: H = 0.7714285714285722, p = 0.6799647735788936.
    const KruskalWallisResult r = kruskalWallis({{2.9, 3.0, 2.5, 2.6, 3.2}, {3.8, 2.7, 4.0, 2.4}, {2.8, 3.4, 3.7, 2.2, 2.0}});
    EXPECT_EQ(r.df, 2);
    EXPECT_EQ(r.n, 14u);
    EXPECT_NEAR(r.h, 0.7714285714285722, 1e-10);
    EXPECT_NEAR(r.p, 0.6799647735788936, 1e-10);
    EXPECT_NEAR(r.epsilonSquared, 0.7714285714285722 / 13.0, 1e-12);
}

TEST(RankTests, KruskalWallisMatchesScipyDocumentationExamples) {
    // scipy.stats.kruskal docs: H = 0.2727272727272734, p = 0.6015081344405895.
    const KruskalWallisResult a = kruskalWallis({{1, 3, 5, 7, 9}, {2, 4, 6, 8, 10}});
    EXPECT_NEAR(a.h, 0.2727272727272734, 1e-10);
    EXPECT_NEAR(a.p, 0.6015081344405895, 1e-10);
    // With heavy ties (the tie correction matters): H = 7.0, p = 0.0301973834223185.
    const KruskalWallisResult b = kruskalWallis({{1, 1, 1}, {2, 2, 2}, {2, 2}});
    EXPECT_NEAR(b.h, 7.0, 1e-10);
    EXPECT_NEAR(b.p, 0.0301973834223185, 1e-10);
}

TEST(RankTests, KruskalWallisOnLikertLikeRatingsMatchesScipy) {
    // SciPy 1.10.1: H = 16.15597910901184, p = 0.00031029423840433785.
    const KruskalWallisResult r = kruskalWallis(
        {{7, 8, 6, 9, 7, 8, 5, 7, 10, 6}, {5, 6, 4, 7, 5, 6, 6, 3, 5, 4, 6}, {4, 4, 5, 3, 6, 2, 5, 4, 3}});
    EXPECT_NEAR(r.h, 16.15597910901184, 1e-9);
    EXPECT_NEAR(r.p, 0.00031029423840433785, 1e-12);
}

TEST(RankTests, KruskalWallisLeavesOutEmptyGroupsAndHandlesAllTied) {
    const KruskalWallisResult withEmpty = kruskalWallis({{1, 3, 5, 7, 9}, {}, {2, 4, 6, 8, 10}});
    EXPECT_EQ(withEmpty.df, 1);
    EXPECT_NEAR(withEmpty.h, 0.2727272727272734, 1e-10);
    const KruskalWallisResult tied = kruskalWallis({{4, 4}, {4, 4, 4}});
    EXPECT_TRUE(tied.allTied);
    EXPECT_EQ(tied.h, 0.0);
    EXPECT_EQ(tied.p, 1.0);
    const KruskalWallisResult one = kruskalWallis({{1, 2}, {}});
    EXPECT_FALSE(one.defined());
    EXPECT_TRUE(std::isnan(one.p));
}

TEST(RankTests, MannWhitneyExactMatchesHollanderWolfeExample) {
    // Hollander & Wolfe (1973) p. 69; R: W = 35, one-sided ("greater") p-value = 0.1272.
    // SciPy exact two-sided: U = 35, p = 0.2544122544122544.
    const MannWhitneyResult r =
        mannWhitney({0.80, 0.83, 1.89, 1.04, 1.45, 1.38, 1.91, 1.64, 0.73, 1.46}, {1.15, 0.88, 0.90, 0.74, 1.21});
    EXPECT_EQ(r.method, PMethod::Exact);
    EXPECT_DOUBLE_EQ(r.u1, 35.0);
    EXPECT_DOUBLE_EQ(r.u2, 15.0);
    EXPECT_NEAR(r.p, 0.2544122544122544, 1e-12);
    EXPECT_NEAR(r.p / 2, 0.1272, 5e-5);  // R's one-sided value, as printed
    EXPECT_NEAR(r.rankBiserial, 0.4, 1e-12);
}

TEST(RankTests, MannWhitneyExactMatchesScipyDocumentationExample) {
    // scipy.stats.mannwhitneyu docs (males vs females): U1 = 17, exact p = 0.1111111111111111.
    const MannWhitneyResult r = mannWhitney({19, 22, 16, 29, 24}, {20, 11, 17, 12});
    EXPECT_EQ(r.method, PMethod::Exact);
    EXPECT_DOUBLE_EQ(r.u1, 17.0);
    EXPECT_NEAR(r.p, 0.1111111111111111, 1e-12);
    EXPECT_NEAR(r.rankBiserial, 0.7, 1e-12);  // (17 - 3) / 20
    // Complete separation of 20 and 20: SciPy exact p = 1.4508889103849684e-11 (2 / C(40, 20)).
    std::vector<double> low, high;
    for (int i = 1; i <= 20; ++i) {
        low.push_back(i);
        high.push_back(20 + i);
    }
    const MannWhitneyResult separated = mannWhitney(low, high);
    EXPECT_EQ(separated.method, PMethod::Exact);
    EXPECT_NEAR(separated.p / 1.4508889103849684e-11, 1.0, 1e-9);
    EXPECT_DOUBLE_EQ(separated.rankBiserial, -1.0);
}

TEST(RankTests, MannWhitneyNormalApproximationWithTiesMatchesScipy) {
    // SciPy 1.10.1, method="asymptotic", use_continuity=True: U1 = 96, p = 0.0036582992453120244.
    const MannWhitneyResult r = mannWhitney({7, 8, 6, 9, 7, 8, 5, 7, 10, 6}, {5, 6, 4, 7, 5, 6, 6, 3, 5, 4, 6});
    EXPECT_EQ(r.method, PMethod::Normal);
    EXPECT_DOUBLE_EQ(r.u1, 96.0);
    EXPECT_NEAR(r.p, 0.0036582992453120244, 1e-12);
    EXPECT_GT(r.z, 0.0);
    // The same in the other order: same p, U and z mirrored.
    const MannWhitneyResult mirrored = mannWhitney({5, 6, 4, 7, 5, 6, 6, 3, 5, 4, 6}, {7, 8, 6, 9, 7, 8, 5, 7, 10, 6});
    EXPECT_DOUBLE_EQ(mirrored.u1, 14.0);
    EXPECT_NEAR(mirrored.p, r.p, 1e-15);
    EXPECT_NEAR(mirrored.z, -r.z, 1e-15);
}

TEST(RankTests, MannWhitneyNormalApproximationWithoutTiesAboveTheExactLimitMatchesScipy) {
    // 22 + 21 distinct values (> 40: normal approximation). SciPy asymptotic: U1 = 98, p = 0.0012851152318451551.
    const std::vector<double> x = {3.1, 4.7, 2.2, 5.9, 6.3, 1.8, 7.7, 4.1, 8.8, 2.9, 5.5,
                                   6.6, 3.3, 9.2, 7.1, 0.4, 4.4, 8.1, 1.2, 6.0, 5.1, 2.5};
    const std::vector<double> y = {4.9, 6.8, 7.4, 5.6, 8.3, 9.9, 3.8, 7.9, 6.2, 10.4, 8.7,
                                   5.3, 9.4, 7.3, 6.5, 11.2, 8.0, 4.6, 9.0, 7.0, 10.1};
    const MannWhitneyResult r = mannWhitney(x, y);
    EXPECT_EQ(r.method, PMethod::Normal);
    EXPECT_DOUBLE_EQ(r.u1, 98.0);
    EXPECT_NEAR(r.p, 0.0012851152318451551, 1e-12);
}

TEST(RankTests, ExactMannWhitneyDistributionIsSymmetricAndSumsToOne) {
    for (std::size_t n1 : {1u, 3u, 7u})
        for (std::size_t n2 : {1u, 4u, 9u}) {
            const double centre = static_cast<double>(n1 * n2) / 2.0;
            EXPECT_DOUBLE_EQ(exactMannWhitneyP(std::floor(centre), n1, n2), 1.0);
            for (std::size_t u = 0; u <= n1 * n2; ++u)
                EXPECT_DOUBLE_EQ(exactMannWhitneyP(static_cast<double>(u), n1, n2),
                                 exactMannWhitneyP(static_cast<double>(n1 * n2 - u), n1, n2));
        }
    // n1 = 1, n2 = 4: U uniform on 0..4, P(U >= 4) = 1/5.
    EXPECT_DOUBLE_EQ(exactMannWhitneyP(0.0, 1, 4), 0.4);
}

TEST(RankTests, MannWhitneyEdgeCases) {
    const MannWhitneyResult empty = mannWhitney({}, {1, 2});
    EXPECT_EQ(empty.method, PMethod::Undefined);
    EXPECT_TRUE(std::isnan(empty.p));
    const MannWhitneyResult tied = mannWhitney({3, 3, 3}, {3, 3});
    EXPECT_EQ(tied.method, PMethod::AllTied);
    EXPECT_EQ(tied.p, 1.0);
    EXPECT_EQ(tied.rankBiserial, 0.0);
}

TEST(RankTests, HolmStepDownAdjustment) {
    // By hand: sorted 0.005, 0.01, 0.03, 0.04 times 4, 3, 2, 1 = 0.02, 0.03, 0.06, 0.04 -> running
    // maximum 0.02, 0.03, 0.06, 0.06. (R: p.adjust(c(0.01, 0.04, 0.03, 0.005), "holm").)
    const std::vector<double> adjusted = holmAdjust({0.01, 0.04, 0.03, 0.005});
    EXPECT_NEAR(adjusted[0], 0.03, 1e-15);
    EXPECT_NEAR(adjusted[1], 0.06, 1e-15);
    EXPECT_NEAR(adjusted[2], 0.06, 1e-15);
    EXPECT_NEAR(adjusted[3], 0.02, 1e-15);
    const std::vector<double> capped = holmAdjust({0.4, 0.6, std::nan("")});
    EXPECT_DOUBLE_EQ(capped[0], 0.8);
    EXPECT_DOUBLE_EQ(capped[1], 0.8);
    EXPECT_TRUE(std::isnan(capped[2]));
}

TEST(RankTests, DescriptivesUseSampleSdTypeSevenQuartilesAndTInterval) {
    // numpy: percentile([1,2,3,4], [25, 50, 75]) = 1.75, 2.5, 3.25; std(ddof=1) = 1.2909944487358056;
    // SciPy: t.ppf(0.975, 3) * sd / 2 = 2.054260256760879.
    const Descriptives d = describe({4, 1, 3, 2});
    EXPECT_EQ(d.n, 4u);
    EXPECT_DOUBLE_EQ(d.mean, 2.5);
    EXPECT_NEAR(d.sd, 1.2909944487358056, 1e-14);
    EXPECT_DOUBLE_EQ(d.q1, 1.75);
    EXPECT_DOUBLE_EQ(d.median, 2.5);
    EXPECT_DOUBLE_EQ(d.q3, 3.25);
    EXPECT_NEAR(d.ci95High - d.mean, 2.054260256760879, 1e-12);
    EXPECT_NEAR(studentT975(23), 2.0686576104190406, 1e-12);  // SciPy t.ppf(0.975, 23)
    const Descriptives one = describe({7});
    EXPECT_DOUBLE_EQ(one.mean, 7);
    EXPECT_TRUE(std::isnan(one.sd));
    EXPECT_TRUE(std::isnan(one.ci95Low));
}

// Under the null hypothesis the tests reject about alpha of the time: 2000 draws of 4 groups of
// 10 (continuous: no ties) and of 2 groups of 24 ratings 1-10 (many ties), SplitMix64.
TEST(RankTests, RejectionRatesUnderTheNullAreNearAlpha) {
    signstim::SplitMix64 rng(20150601);
    const int runs = 2000;
    int kwContinuous = 0, kwRatings = 0, mwRatings = 0, mwExact = 0;
    for (int run = 0; run < runs; ++run) {
        std::vector<std::vector<double>> continuous(4), ratings(4);
        for (int g = 0; g < 4; ++g)
            for (int i = 0; i < 10; ++i) continuous[g].push_back(rng.uniform());
        for (int g = 0; g < 4; ++g)
            for (int i = 0; i < 24; ++i) ratings[g].push_back(static_cast<double>(1 + rng.below(10)));
        kwContinuous += kruskalWallis(continuous).p < 0.05;
        kwRatings += kruskalWallis(ratings).p < 0.05;
        mwRatings += mannWhitney(ratings[0], ratings[1]).p < 0.05;
        mwExact += mannWhitney(continuous[0], continuous[1]).p < 0.05;
    }
    // Binomial(2000, 0.05): SD 0.0049; the bounds are about 3 SD. At this seed: 86, 115, 98 and
    // 79 of 2000 (4.3 %, 5.75 %, 4.9 %, 3.95 %); the exact test's discrete distribution cannot
    // reach 0.05 exactly (its largest level below it for 10 and 10 is 0.043).
    RecordProperty("rates_per_2000", std::to_string(kwContinuous) + " " + std::to_string(kwRatings) + " " + std::to_string(mwRatings) +
                                         " " + std::to_string(mwExact));
    for (const int count : {kwContinuous, kwRatings, mwRatings, mwExact}) {
        const double rate = static_cast<double>(count) / runs;
        EXPECT_GT(rate, 0.030) << count;
        EXPECT_LT(rate, 0.065) << count;
    }
}

}  // namespace
