#pragma once
// Rank statistics for the paper's analysis (docs/analysis.md, "Statistics"): descriptives with
// a t-based 95 % confidence interval of the mean, the Kruskal–Wallis H test across versions,
// the Mann–Whitney U test for pairs of versions, Holm's step-down correction, and effect sizes
// (epsilon squared for H, the rank-biserial correlation for U).
//
// Ties get midranks and the usual tie corrections. Distribution functions (chi-squared,
// normal, Student's t) are Boost.Math's; nothing here draws random numbers. Functions are
// pure: same numbers in, same numbers out.
//
// "Not defined" is NaN in these structs (the SD of one value, a test of an empty group);
// writers turn NaN into null / an empty cell, never the text "nan".
#include <cstddef>
#include <string>
#include <vector>

namespace signstim::analysis {

struct Descriptives {
    std::size_t n = 0;
    double mean = 0.0;
    double sd = 0.0;        // sample standard deviation (n - 1); NaN for n < 2
    double ci95Low = 0.0;   // mean -/+ t(0.975, n - 1) * sd / sqrt(n); NaN for n < 2
    double ci95High = 0.0;
    double median = 0.0;
    double q1 = 0.0, q3 = 0.0;  // quartiles by linear interpolation (Hyndman & Fan type 7: R's and numpy's default)
    double minimum = 0.0, maximum = 0.0;
};

// NaN everywhere but n = 0 for an empty sample.
Descriptives describe(const std::vector<double>& values);

// Quantile `probability` (0..1) of sorted values, type 7. NaN when empty.
double quantileSorted(const std::vector<double>& sorted, double probability);

// 1-based ranks of `values`, ties getting the mean of the ranks they span (midranks).
std::vector<double> midranks(const std::vector<double>& values);

// Sum of t^3 - t over groups of tied values (t = size of the group): the tie term of H and U.
double tieTerm(const std::vector<double>& values);

struct KruskalWallisResult {
    std::size_t n = 0;       // observations in the groups that have any
    std::size_t groups = 0;  // groups with at least one observation
    double h = 0.0;          // tie-corrected H
    int df = 0;              // groups - 1
    double p = 0.0;          // upper tail of chi-squared(df) at H; NaN when not defined
    double epsilonSquared = 0.0;  // H / (n - 1) (Tomczak & Tomczak 2014): 0 none .. 1 complete separation
    bool allTied = false;    // every value equal: H = 0 and p = 1 (the permutation distribution is a point)
    bool defined() const { return groups >= 2; }  // H needs two non-empty groups
};

// Empty groups are left out (and so do not count towards df).
KruskalWallisResult kruskalWallis(const std::vector<std::vector<double>>& groups);

enum class PMethod {
    Exact,      // no ties and n1 + n2 <= kExactMannWhitneyLimit: the exact permutation distribution of U
    Normal,     // normal approximation, tie-corrected variance, continuity correction 0.5
    AllTied,    // every value equal: z = 0, p = 1
    Undefined,  // a group is empty: p NaN
};
std::string methodName(PMethod method);  // "exact", "normal approximation", "all values tied", "not defined"

inline constexpr std::size_t kExactMannWhitneyLimit = 40;  // C(40, 20) < 2^53: counts stay exact in doubles

struct MannWhitneyResult {
    std::size_t n1 = 0, n2 = 0;
    double u1 = 0.0;  // U of the first sample: pairs (x, y) with x > y, ties counting one half
    double u2 = 0.0;  // n1 * n2 - u1
    double z = 0.0;   // signed (positive when the first sample tends to be larger), continuity-corrected; 0 for Exact
    double p = 0.0;   // two-sided
    double rankBiserial = 0.0;  // (u1 - u2) / (n1 n2), -1 .. 1 (Kerby 2014); positive: the first is larger
    PMethod method = PMethod::Undefined;
};

MannWhitneyResult mannWhitney(const std::vector<double>& first, const std::vector<double>& second);

// Two-sided exact p of U for samples of n1 and n2 without ties: 2 P(U >= max(u, n1 n2 - u)),
// at most 1. For the tests; mannWhitney uses it when it applies.
double exactMannWhitneyP(double u, std::size_t n1, std::size_t n2);

// Holm (1979) step-down adjusted p-values in the order given: sort ascending, multiply the
// i-th smallest (0-based) by m - i, carry the running maximum, cap at 1. NaN entries stay NaN
// and do not count towards m.
std::vector<double> holmAdjust(const std::vector<double>& p);

// Two-sided quantile t(0.975, df) of Student's t (df >= 1).
double studentT975(double df);

}  // namespace signstim::analysis
