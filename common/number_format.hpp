#pragma once
// Numbers echoed in messages: the shortest text that reads back as the same double, so a value
// refused for differing from a limit past the 6th digit shows why ("1.0000001", not "1.000000").
#include <string>

namespace signstim {

// Shortest round-trip decimal ("0.1", "1e+308", "-2000", "1.0000001"); "nan", "inf", "-inf" for
// the non-finite values.
std::string formatNumber(double value);

// Fixed-point text with exactly `decimals` digits after the point ("12.345", "0.500", "-3.000"),
// the same in every locale; "nan", "inf", "-inf" for the non-finite values. For columns of a
// table (durations to the millisecond) where every row should read alike.
std::string formatFixed(double value, int decimals);

// "expected MIN to MAX UNIT, got VALUE" (UNIT may be empty): the one wording of range errors.
std::string rangeMessage(double minimum, double maximum, const std::string& unit, double value);

}  // namespace signstim
