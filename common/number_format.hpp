#pragma once
// Numbers echoed in messages: the shortest text that reads back as the same double, so a value
// refused for differing from a limit past the 6th digit shows why ("1.0000001", not "1.000000").
#include <string>

namespace signstim {

// Shortest round-trip decimal ("0.1", "1e+308", "-2000", "1.0000001"); "nan", "inf", "-inf" for
// the non-finite values.
std::string formatNumber(double value);

// "expected MIN to MAX UNIT, got VALUE" (UNIT may be empty): the one wording of range errors.
std::string rangeMessage(double minimum, double maximum, const std::string& unit, double value);

}  // namespace signstim
