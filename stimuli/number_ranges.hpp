#pragma once
// The physical ranges every number read from a data file is checked against, so that a typo
// such as 1e308 is refused with its file, line and field instead of reaching the output as
// null, inf or nan. Where the SPEC fixes a range it is cited; the others are [D] choices,
// generous but finite, documented in docs/verbs.md and docs/hand.md ("Ranges of numbers").
#include <string>

namespace signstim::stimuli {

struct NumberRange {
    double minimum = 0.0;
    double maximum = 0.0;
    const char* unit = "";  // "mm", "s", "degrees"; "" for unitless
    bool contains(double value) const { return value >= minimum && value <= maximum; }  // false for NaN
};

// [D] Positions in the signing-space frame (docs/verbs.md): an arm reaches less than 1 m from
// the chest; twice that is surely a mistake.
inline constexpr NumberRange kSigningSpacePositionRange{-2000.0, 2000.0, "mm"};
// [D] Components of a direction (fingers, palm), normalised on load: any scale up to 1000.
inline constexpr NumberRange kDirectionComponentRange{-1000.0, 1000.0, ""};
// [D] Keyframe times: a verb lasts a second or two; a minute is surely a mistake (and a time
// of 1e9 s would render practically for ever).
inline constexpr NumberRange kKeyframeTimeRange{0.0, 60.0, "s"};
// [D] Angles written in degrees (corpus roll/pitch/yaw, sensor azimuth/elevation/roll): one
// turn either way, so exports in 0..360 and -180..180 both load.
inline constexpr NumberRange kAngleDegreesRange{-360.0, 360.0, "degrees"};
// [D] Coefficients of the trained polynomials (mm or radians per unit of arc position) and
// other unitless model numbers: |s|, |o| <= 1, so a coefficient is of the order of the
// positions it predicts; 1e5 is far beyond any fit and still finite after a cubic.
inline constexpr NumberRange kModelCoefficientRange{-1.0e5, 1.0e5, ""};
// [D] Covariance entries of the mixture of right-hand locations: (2000 mm)² on the diagonal.
inline constexpr NumberRange kCovarianceRange{-4.0e6, 4.0e6, "mm²"};
// [D] Sensor positions in the tracker's frame: trackers reach a few metres; 10 m is a mistake.
inline constexpr NumberRange kSensorPositionRange{-10000.0, 10000.0, "mm"};
// [D] Sample times of a recording: up to a day (86400 s), negative times allowed (some trackers
// count from a trigger).
inline constexpr NumberRange kSampleTimeRange{-86400.0, 86400.0, "s"};

// Throws InputError(file, line, field, "expected MIN to MAX UNIT, got VALUE") when `value` is
// outside `range` or not finite.
void checkInRange(double value, const NumberRange& range, const std::string& file, int line, const std::string& field);

}  // namespace signstim::stimuli
