#include "analysis/rank_tests.hpp"

#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace signstim::analysis {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

void requireFinite(const std::vector<double>& values) {
    for (double v : values)
        if (!std::isfinite(v)) throw std::invalid_argument("rank statistics: a value is not finite");
}

// Upper tail of the standard normal at z (Boost.Math: complement, accurate far in the tail).
double normalUpperTail(double z) { return boost::math::cdf(boost::math::complement(boost::math::normal_distribution<double>(), z)); }

}  // namespace

double quantileSorted(const std::vector<double>& sorted, double probability) {
    if (sorted.empty()) return kNaN;
    const double h = (static_cast<double>(sorted.size()) - 1.0) * probability;
    const std::size_t below = static_cast<std::size_t>(std::floor(h));
    const std::size_t above = std::min(below + 1, sorted.size() - 1);
    return sorted[below] + (h - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

double studentT975(double df) {
    return boost::math::quantile(boost::math::students_t_distribution<double>(df), 0.975);
}

Descriptives describe(const std::vector<double>& values) {
    requireFinite(values);
    Descriptives d;
    d.n = values.size();
    if (values.empty()) {
        d.mean = d.sd = d.ci95Low = d.ci95High = d.median = d.q1 = d.q3 = d.minimum = d.maximum = kNaN;
        return d;
    }
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    const double n = static_cast<double>(d.n);
    // Summed in sorted order: the same bytes whatever order the observations came in.
    d.mean = std::accumulate(sorted.begin(), sorted.end(), 0.0) / n;
    d.minimum = sorted.front();
    d.maximum = sorted.back();
    d.median = quantileSorted(sorted, 0.5);
    d.q1 = quantileSorted(sorted, 0.25);
    d.q3 = quantileSorted(sorted, 0.75);
    if (d.n < 2) {
        d.sd = d.ci95Low = d.ci95High = kNaN;
        return d;
    }
    double squares = 0.0;
    for (double v : sorted) squares += (v - d.mean) * (v - d.mean);
    d.sd = std::sqrt(squares / (n - 1.0));
    const double half = studentT975(n - 1.0) * d.sd / std::sqrt(n);
    d.ci95Low = d.mean - half;
    d.ci95High = d.mean + half;
    return d;
}

std::vector<double> midranks(const std::vector<double>& values) {
    requireFinite(values);
    std::vector<std::size_t> order(values.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
    std::vector<double> ranks(values.size());
    for (std::size_t i = 0; i < order.size();) {
        std::size_t j = i;
        while (j + 1 < order.size() && values[order[j + 1]] == values[order[i]]) ++j;
        const double rank = (static_cast<double>(i) + static_cast<double>(j)) / 2.0 + 1.0;  // mean of ranks i+1 .. j+1
        for (std::size_t k = i; k <= j; ++k) ranks[order[k]] = rank;
        i = j + 1;
    }
    return ranks;
}

double tieTerm(const std::vector<double>& values) {
    std::vector<double> sorted = values;
    std::sort(sorted.begin(), sorted.end());
    double term = 0.0;
    for (std::size_t i = 0; i < sorted.size();) {
        std::size_t j = i;
        while (j < sorted.size() && sorted[j] == sorted[i]) ++j;
        const double t = static_cast<double>(j - i);
        term += t * t * t - t;
        i = j;
    }
    return term;
}

KruskalWallisResult kruskalWallis(const std::vector<std::vector<double>>& groups) {
    KruskalWallisResult r;
    std::vector<double> pooled;
    std::vector<std::size_t> sizes;
    for (const std::vector<double>& g : groups) {
        if (g.empty()) continue;
        pooled.insert(pooled.end(), g.begin(), g.end());
        sizes.push_back(g.size());
    }
    r.n = pooled.size();
    r.groups = sizes.size();
    if (!r.defined()) {
        r.h = r.p = r.epsilonSquared = kNaN;
        return r;
    }
    r.df = static_cast<int>(r.groups) - 1;
    const std::vector<double> ranks = midranks(pooled);
    const double n = static_cast<double>(r.n);
    const double ties = tieTerm(pooled);
    const double correction = 1.0 - ties / (n * n * n - n);
    if (correction <= 0.0) {
        r.allTied = true;
        r.h = 0.0;
        r.p = 1.0;
        r.epsilonSquared = 0.0;
        return r;
    }
    double sum = 0.0;
    std::size_t at = 0;
    for (std::size_t size : sizes) {
        double rankSum = 0.0;
        for (std::size_t i = 0; i < size; ++i) rankSum += ranks[at + i];
        at += size;
        sum += rankSum * rankSum / static_cast<double>(size);
    }
    const double uncorrected = 12.0 / (n * (n + 1.0)) * sum - 3.0 * (n + 1.0);
    r.h = std::max(0.0, uncorrected / correction);  // rounding can leave -1e-15 for identical rank sums
    r.p = boost::math::cdf(boost::math::complement(boost::math::chi_squared_distribution<double>(r.df), r.h));
    r.epsilonSquared = r.h / (n - 1.0);  // = H / ((n^2 - 1) / (n + 1))
    return r;
}

std::string methodName(PMethod method) {
    switch (method) {
        case PMethod::Exact: return "exact";
        case PMethod::Normal: return "normal approximation";
        case PMethod::AllTied: return "all values tied";
        case PMethod::Undefined: return "not defined";
    }
    return "not defined";
}

double exactMannWhitneyP(double u, std::size_t n1, std::size_t n2) {
    if (n1 + n2 > kExactMannWhitneyLimit) throw std::invalid_argument("exactMannWhitneyP: samples too large for exact counts");
    // counts[k]: arrangements of n1 first and n2 second values whose U is k — the coefficients of
    // the Gaussian binomial [n1 + n2 choose n1]_q, built one sample size at a time:
    // f(i, j) = f(i - 1, j) shifted by j + f(i, j - 1) (the largest value belongs to the first or
    // the second sample).
    const std::size_t maxU = n1 * n2;
    std::vector<std::vector<std::vector<double>>> f(n1 + 1, std::vector<std::vector<double>>(n2 + 1));
    for (std::size_t i = 0; i <= n1; ++i)
        for (std::size_t j = 0; j <= n2; ++j) {
            std::vector<double>& c = f[i][j];
            c.assign(i * j + 1, 0.0);
            if (i == 0 || j == 0) {
                c[0] = 1.0;
                continue;
            }
            const std::vector<double>& firstLargest = f[i - 1][j];   // the largest is a first value: it beats all j
            const std::vector<double>& secondLargest = f[i][j - 1];  // the largest is a second value: it adds nothing
            for (std::size_t k = 0; k < firstLargest.size(); ++k) c[k + j] += firstLargest[k];
            for (std::size_t k = 0; k < secondLargest.size(); ++k) c[k] += secondLargest[k];
        }
    const std::vector<double>& counts = f[n1][n2];
    const double total = std::accumulate(counts.begin(), counts.end(), 0.0);
    const double larger = std::max(u, static_cast<double>(maxU) - u);
    double tail = 0.0;
    for (std::size_t k = 0; k <= maxU; ++k)
        if (static_cast<double>(k) >= larger - 1e-9) tail += counts[k];
    return std::min(1.0, 2.0 * tail / total);
}

MannWhitneyResult mannWhitney(const std::vector<double>& first, const std::vector<double>& second) {
    MannWhitneyResult r;
    r.n1 = first.size();
    r.n2 = second.size();
    if (first.empty() || second.empty()) {
        r.u1 = r.u2 = r.z = r.p = r.rankBiserial = kNaN;
        r.method = PMethod::Undefined;
        return r;
    }
    std::vector<double> pooled = first;
    pooled.insert(pooled.end(), second.begin(), second.end());
    const std::vector<double> ranks = midranks(pooled);
    const double n1 = static_cast<double>(r.n1), n2 = static_cast<double>(r.n2), n = n1 + n2;
    double rankSum = 0.0;
    for (std::size_t i = 0; i < r.n1; ++i) rankSum += ranks[i];
    r.u1 = rankSum - n1 * (n1 + 1.0) / 2.0;
    r.u2 = n1 * n2 - r.u1;
    r.rankBiserial = (r.u1 - r.u2) / (n1 * n2);
    const double ties = tieTerm(pooled);
    if (ties == 0.0 && r.n1 + r.n2 <= kExactMannWhitneyLimit) {
        r.method = PMethod::Exact;
        r.z = 0.0;
        r.p = exactMannWhitneyP(r.u1, r.n1, r.n2);
        return r;
    }
    const double variance = n1 * n2 / 12.0 * ((n + 1.0) - ties / (n * (n - 1.0)));
    if (variance <= 0.0) {
        r.method = PMethod::AllTied;
        r.z = 0.0;
        r.p = 1.0;
        return r;
    }
    r.method = PMethod::Normal;
    const double deviation = r.u1 - n1 * n2 / 2.0;
    const double corrected = std::max(0.0, std::abs(deviation) - 0.5);  // continuity correction
    const double z = corrected / std::sqrt(variance);
    r.z = deviation < 0.0 ? -z : z;
    r.p = std::min(1.0, 2.0 * normalUpperTail(z));
    return r;
}

std::vector<double> holmAdjust(const std::vector<double>& p) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < p.size(); ++i)
        if (!std::isnan(p[i])) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p[a] < p[b]; });
    std::vector<double> adjusted(p.size(), kNaN);
    const double m = static_cast<double>(order.size());
    double running = 0.0;
    for (std::size_t i = 0; i < order.size(); ++i) {
        running = std::max(running, std::min(1.0, (m - static_cast<double>(i)) * p[order[i]]));
        adjusted[order[i]] = running;
    }
    return adjusted;
}

}  // namespace signstim::analysis
