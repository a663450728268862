#pragma once
// Numbers as the report, the figures and the tables show them (locale-independent; never
// "nan": the callers show an empty cell or a dash for a value that is not defined).
#include <string>

namespace signstim::analysis {

// "p = 0.046", "p = 0.0061", "p < 0.001"; "p = 1" for 1.
std::string formatP(double p);
// The p value alone in the same style: "0.046", "0.0061", "< 0.001".
std::string formatPValue(double p);
// Fixed decimals ("12.34"); "" for NaN or infinity.
std::string fixedOrEmpty(double value, int decimals);
// 6 significant digits, shortest form ("0.123457", "1.5e-07", "24"); "" for NaN or infinity.
// The precision of results.csv and summary.json: enough for any table, and free of the
// last-bit noise that differs between libm versions.
std::string significant6(double value);
// `value` rounded to 6 significant digits (the number significant6 writes); NaN stays NaN.
double roundSignificant6(double value);
// "42%" for 0.42.
std::string percent(double proportion);

}  // namespace signstim::analysis
