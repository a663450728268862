#include "signer/settled_pace.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace signstim::signer {

RateBounds offsetRateBounds(const glm::dvec3& velocity, const glm::dvec3& perUnit, double limit) {
    // |v + x·u|² ≤ m²: |u|²·x² + 2(v·u)·x + |v|² − m² ≤ 0, between its roots (m ≥ |v|: 0 is inside).
    constexpr double kUnbounded = std::numeric_limits<double>::infinity();
    const double uu = glm::dot(perUnit, perUnit);
    if (uu < 1e-12) return {-kUnbounded, kUnbounded};
    const double m = std::max(limit, glm::length(velocity));
    const double vu = glm::dot(velocity, perUnit);
    const double root = std::sqrt(std::max(0.0, vu * vu - uu * (glm::dot(velocity, velocity) - m * m)));
    return {std::min(0.0, (-vu - root) / uu), std::max(0.0, (-vu + root) / uu)};
}

std::vector<float> rateLimitedEnvelope(const std::vector<double>& times, const std::vector<float>& need,
                                       const std::vector<RateBounds>& bounds) {
    // Difference constraints on a path, lo·dt ≤ s[i+1] − s[i] ≤ hi·dt with lo ≤ 0 ≤ hi: a pass
    // forward (how fast it may shrink) and one back (how fast it may grow) give the least s.
    std::vector<float> s = need;
    for (std::size_t i = 0; i + 1 < s.size(); ++i)
        s[i + 1] = std::max(s[i + 1], static_cast<float>(s[i] + bounds[i].lo * (times[i + 1] - times[i])));
    for (std::size_t i = s.size() - 1; i-- > 0;)
        s[i] = std::max(s[i], static_cast<float>(s[i + 1] - bounds[i].hi * (times[i + 1] - times[i])));
    return s;
}

std::vector<double> easedProgress(const std::vector<double>& times, const std::vector<double>& blend,
                                  const std::vector<RateBounds>& bounds) {
    const std::size_t n = times.size();
    std::vector<double> progress(n, 0.0);
    if (n < 2) return progress;
    // Per interval: the headroom's rate (hi; 1e6/s: no bound) and the keys' blend's.
    std::vector<double> headroom(n - 1), keys(n - 1), dt(n - 1);
    double whole = 0.0;
    for (std::size_t i = 0; i + 1 < n; ++i) {
        dt[i] = times[i + 1] - times[i];
        headroom[i] = std::min(1e6, bounds[i].hi);
        keys[i] = std::max(0.0, blend[i + 1] - blend[i]) / dt[i];
        whole += headroom[i] * dt[i];
    }
    // rate = min(headroom, c·keys' rate): c = 1 where the headroom allows the keys' blend
    // throughout; else c > 1, found by bisection, puts what the headroom cuts where the keys'
    // blend moves and the headroom allows. Where even the whole headroom is less than the
    // change, rate = headroom / whole.
    const auto total = [&](double c) {
        double sum = 0.0;
        for (std::size_t i = 0; i + 1 < n; ++i) sum += std::min(headroom[i], c * keys[i]) * dt[i];
        return sum;
    };
    std::vector<double> rate(n - 1);
    if (!(whole > 1.0)) {
        for (std::size_t i = 0; i + 1 < n; ++i) rate[i] = whole > 0.0 ? headroom[i] / whole : 1.0 / (times.back() - times.front());
    } else {
        double low = 0.0, high = 1.0;
        while (total(high) < 1.0 && high < 1e12) high *= 2.0;
        // [D] 60 halvings: c to double precision.
        for (int k = 0; k < 60; ++k) (total(0.5 * (low + high)) < 1.0 ? low : high) = 0.5 * (low + high);
        const double sum = total(high);
        for (std::size_t i = 0; i + 1 < n; ++i) rate[i] = std::min(headroom[i], high * keys[i]) / sum;
    }
    for (std::size_t i = 0; i + 1 < n; ++i) progress[i + 1] = std::min(1.0, progress[i] + rate[i] * dt[i]);
    progress.back() = 1.0;
    return progress;
}

}  // namespace signstim::signer
