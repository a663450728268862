#include "common/number_format.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

using signstim::formatNumber;

TEST(NumberFormat, ShortestTextThatReadsBackTheSameDouble) {
    EXPECT_EQ(formatNumber(1.0000001), "1.0000001");  // %f would print 1.000000
    EXPECT_EQ(formatNumber(0.1), "0.1");
    EXPECT_EQ(formatNumber(-2000.0), "-2000");
    EXPECT_EQ(formatNumber(1e308), "1e+308");
    EXPECT_EQ(formatNumber(-0.0), "0");
    EXPECT_EQ(formatNumber(1e9), "1000000000");  // everyday magnitudes in plain notation
    EXPECT_EQ(formatNumber(-1e5), "-100000");
    EXPECT_EQ(formatNumber(0.00012), "0.00012");
    EXPECT_EQ(formatNumber(1e-300), "1e-300");
    EXPECT_EQ(std::stod(formatNumber(0.1 + 0.2)), 0.1 + 0.2);
}

TEST(NumberFormat, NonFiniteValuesAreNamed) {
    EXPECT_EQ(formatNumber(std::numeric_limits<double>::infinity()), "inf");
    EXPECT_EQ(formatNumber(-std::numeric_limits<double>::infinity()), "-inf");
    EXPECT_EQ(formatNumber(std::numeric_limits<double>::quiet_NaN()), "nan");
}

TEST(NumberFormat, RangeMessageNamesTheRangeTheUnitAndTheValue) {
    EXPECT_EQ(signstim::rangeMessage(-2000, 2000, "mm", 1e308), "expected -2000 to 2000 mm, got 1e+308");
    EXPECT_EQ(signstim::rangeMessage(0, 1, "", 1.0000001), "expected 0 to 1, got 1.0000001");
}

TEST(NumberFormat, FixedTextHasExactlyTheAskedDecimals) {
    using signstim::formatFixed;
    EXPECT_EQ(formatFixed(12.3456, 3), "12.346");
    EXPECT_EQ(formatFixed(0.5, 3), "0.500");
    EXPECT_EQ(formatFixed(2.0, 0), "2");
    EXPECT_EQ(formatFixed(-3.0, 3), "-3.000");
    EXPECT_EQ(formatFixed(-0.0004, 3), "0.000");  // no sign on a zero
    EXPECT_EQ(formatFixed(1e20, 1), "100000000000000000000.0");
    EXPECT_EQ(formatFixed(std::numeric_limits<double>::quiet_NaN(), 3), "nan");
    EXPECT_EQ(formatFixed(-std::numeric_limits<double>::infinity(), 3), "-inf");
    EXPECT_THROW(formatFixed(1.0, -1), std::invalid_argument);
}
