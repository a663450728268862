#pragma once
// How fast a settled touch's offsets (signer/timeline_clip.hpp, settleTouches) may change: only
// as fast as the headroom the wrist's own motion leaves under SPEC §6.2's peak speed. The
// timeline's pacer times items and transitions by the keys' posed path, without the offsets;
// an offset that grows or shrinks while the wrist already moves near the limit would take it
// past. So the offsets change where the wrist is slow (the ends of a transition, a hold), and
// never make it faster than the limit, or than it already was. Plain math on sampled paths.
#include <glm/glm.hpp>

#include <vector>

namespace signstim::signer {

// The rates x (units per second) at which an offset of `perUnitMm` (mm per unit) may change
// while the wrist moves at `velocityMmPerSecond`: |velocity + x·perUnit| ≤ max(limit, |velocity|).
// lo ≤ 0 ≤ hi.
struct RateBounds {
    double lo = 0.0, hi = 0.0;
};
RateBounds offsetRateBounds(const glm::dvec3& velocityMmPerSecond, const glm::dvec3& perUnitMm, double limitMmPerSecond);

// The least way out s ≥ `need` (mm, at `times`, ascending) whose change between neighbouring
// instants i and i+1 is within bounds[i]·(t[i+1] − t[i]): the need raised ahead of where it
// grows and held after where it shrinks, as slowly as the bounds ask.
std::vector<float> rateLimitedEnvelope(const std::vector<double>& times, const std::vector<float>& need,
                                       const std::vector<RateBounds>& bounds);

// An offset's progress from 0 to 1 over a transition (at `times`, ascending, its start first
// and its end last), whose rate between instants i and i+1 may be up to bounds[i].hi (the
// headroom, offsetRateBounds): the keys' own blend there (`blend`, 0 to 1 at `times`), as the
// keys move, where the headroom allows it; where it does not, the rate is the headroom's and
// what it leaves goes where the keys' blend moves and the headroom allows. Where the
// headroom's whole is less than the change, the rate is the headroom's in proportion (the
// limit passed as little as may be).
std::vector<double> easedProgress(const std::vector<double>& times, const std::vector<double>& blend,
                                  const std::vector<RateBounds>& bounds);

}  // namespace signstim::signer
