// How fast a settled touch's offsets may change (signer/settled_pace.hpp): within the headroom
// the wrist's own motion leaves under SPEC §6.2's limit, never making a wrist faster than the
// limit or than it was; synthetic paths.
#include "signer/settled_pace.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace signstim::signer;

TEST(SettledPace, TheRateBoundsKeepTheWristWithinTheLimitOrItsOwnSpeed) {
    const double limit = 2450.0;
    // Synthetic velocities (mm/s) below and above the limit, and offsets along, against and
    // across them.
    const std::vector<glm::dvec3> velocities{{0, 0, 0}, {1000, 0, 0}, {2400, 300, 0}, {3000, 0, 0}, {-500, 1500, 800}};
    const std::vector<glm::dvec3> offsets{{40, 0, 0}, {-40, 0, 0}, {0, 25, 0}, {10, -20, 30}};
    for (const glm::dvec3& v : velocities)
        for (const glm::dvec3& u : offsets) {
            const RateBounds b = offsetRateBounds(v, u, limit);
            const double allowed = std::max(limit, glm::length(v));
            EXPECT_LE(b.lo, 0.0);
            EXPECT_GE(b.hi, 0.0);
            EXPECT_NEAR(glm::length(v + b.lo * u), allowed, 1e-6 * allowed);
            EXPECT_NEAR(glm::length(v + b.hi * u), allowed, 1e-6 * allowed);
            EXPECT_LE(glm::length(v + 0.5 * (b.lo + b.hi) * u), allowed * (1 + 1e-9));
        }
}

TEST(SettledPace, TheEnvelopeMeetsEveryNeedAndChangesNoFasterThanItsBounds) {
    // A synthetic need: a touch 30 mm deep for a moment in the middle, 5 mm at the ends.
    std::vector<double> times;
    std::vector<float> need;
    std::vector<RateBounds> bounds;
    for (int i = 0; i <= 30; ++i) {
        times.push_back(i / 60.0);
        need.push_back(i == 15 ? 30.0f : i == 0 || i == 30 ? 5.0f : 0.0f);
        if (i < 30) bounds.push_back({i < 15 ? -300.0 : -100.0, i < 15 ? 200.0 : 300.0});
    }
    const std::vector<float> s = rateLimitedEnvelope(times, need, bounds);
    for (std::size_t i = 0; i < s.size(); ++i) EXPECT_GE(s[i], need[i]);
    for (std::size_t i = 0; i + 1 < s.size(); ++i) {
        const double rate = (s[i + 1] - s[i]) / (times[i + 1] - times[i]);
        EXPECT_GE(rate, bounds[i].lo - 1e-3) << i;
        EXPECT_LE(rate, bounds[i].hi + 1e-3) << i;
    }
    // The least such: it touches the need where it peaks, and falls off only as its bounds ask.
    EXPECT_FLOAT_EQ(s[15], 30.0f);
    EXPECT_NEAR(s[14], 30.0 - 200.0 / 60.0, 1e-4);
    EXPECT_NEAR(s[16], 30.0 - 100.0 / 60.0, 1e-4);
}

TEST(SettledPace, AnOffsetFollowsTheKeysWhereTheHeadroomAllowsAndNeverOutrunsIt) {
    std::vector<double> times, blend;
    for (int i = 0; i <= 48; ++i) {
        const double u = i / 48.0;
        times.push_back(0.2 * u);
        blend.push_back(u * u * u * (10.0 - 15.0 * u + 6.0 * u * u));  // minimum jerk
    }
    // Ample headroom: the keys' blend itself.
    const std::vector<RateBounds> ample(48, RateBounds{-1e6, 1e6});
    const std::vector<double> same = easedProgress(times, blend, ample);
    for (std::size_t i = 0; i < same.size(); ++i) EXPECT_NEAR(same[i], blend[i], 1e-9) << i;
    // Little headroom in the middle (a wrist near the limit there): the rate stays within it,
    // the progress still goes from 0 to 1, and more of it happens near the ends.
    std::vector<RateBounds> tight;
    for (int i = 0; i < 48; ++i) tight.push_back({-1.0, i >= 16 && i < 32 ? 1.0 : 1e6});
    const std::vector<double> p = easedProgress(times, blend, tight);
    EXPECT_DOUBLE_EQ(p.front(), 0.0);
    EXPECT_DOUBLE_EQ(p.back(), 1.0);
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
        EXPECT_GE(p[i + 1], p[i]);
        EXPECT_LE((p[i + 1] - p[i]) / (times[i + 1] - times[i]), tight[i].hi * (1 + 1e-9)) << i;
    }
    EXPECT_LT(p[32] - p[16], blend[32] - blend[16]);
}
