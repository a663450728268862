#include "hand/contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace signstim::hand {
namespace {

constexpr float kTwoPi = 6.28318530717958647f;

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection §5.1.5).
glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b,
                                 const glm::vec3& c) {
    const glm::vec3 ab = b - a, ac = c - a, ap = p - a;
    const float d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0f && d2 <= 0.0f) return a;
    const glm::vec3 bp = p - b;
    const float d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0f && d4 <= d3) return b;
    const float vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0f && d1 >= 0.0f && d3 <= 0.0f) return a + (d1 / (d1 - d3)) * ab;
    const glm::vec3 cp = p - c;
    const float d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0f && d5 <= d6) return c;
    const float vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0f && d2 >= 0.0f && d6 <= 0.0f) return a + (d2 / (d2 - d6)) * ac;
    const float va = d3 * d6 - d5 * d4;
    if (va <= 0.0f && (d4 - d3) >= 0.0f && (d5 - d6) >= 0.0f) {
        return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    }
    const float denom = 1.0f / (va + vb + vc);
    return a + ab * (vb * denom) + ac * (vc * denom);
}

}  // namespace

bool sphereTouchesFacePaper(const BoxVertices& box, int face, const glm::vec3& centre, float radius,
                            float angleToleranceRad) {
    if (face < 0 || face >= 6) throw std::invalid_argument("sphereTouchesFacePaper: face must be 0..5");
    const auto& f = kBoxFaces[face];
    const glm::vec3 v1 = box[f[0]], v2 = box[f[1]], v3 = box[f[2]], v4 = box[f[3]];
    // SPEC §2.6 [P]: k = (v₁ − v₂) × (v₄ − v₁), k₄ = −k·v₁.
    const glm::vec3 k = glm::cross(v1 - v2, v4 - v1);
    const float kk = glm::dot(k, k);
    if (!(kk > 0.0f)) return false;  // degenerate face
    const float k4 = -glm::dot(k, v1);
    const float signedPlane = glm::dot(k, centre) + k4;
    const float distance = std::abs(signedPlane) / std::sqrt(kk);
    if (distance > radius) return false;
    const glm::vec3 projected = centre - (signedPlane / kk) * k;
    // Angle sum at the projected point: 360° exactly when it lies inside the (convex) face.
    const std::array<glm::vec3, 4> v = {v1, v2, v3, v4};
    double sum = 0.0;
    for (int i = 0; i < 4; ++i) {
        const glm::vec3 a = v[i] - projected, b = v[(i + 1) % 4] - projected;
        const float la = glm::length(a), lb = glm::length(b);
        if (la < 1e-6f || lb < 1e-6f) return true;  // on a vertex
        sum += std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0f, 1.0f));
    }
    return std::abs(sum - kTwoPi) < angleToleranceRad;
}

bool sphereTouchesBoxPaper(const BoxVertices& box, const glm::vec3& centre, float radius,
                           float angleToleranceRad) {
    for (int face = 0; face < 6; ++face) {
        if (sphereTouchesFacePaper(box, face, centre, radius, angleToleranceRad)) return true;
    }
    return false;
}

float signedDistanceToBox(const BoxVertices& box, const glm::vec3& point) {
    glm::vec3 centroid(0.0f);
    for (const auto& v : box) centroid += v;
    centroid *= 0.125f;
    float best = std::numeric_limits<float>::max();
    bool inside = true;
    for (const auto& f : kBoxFaces) {
        // Each quad as two triangles; the outward side is the one away from the centroid.
        const std::array<std::array<int, 3>, 2> triangles = {{{f[0], f[1], f[2]}, {f[0], f[2], f[3]}}};
        for (const auto& t : triangles) {
            const glm::vec3 a = box[t[0]], b = box[t[1]], c = box[t[2]];
            best = std::min(best, glm::distance(point, closestPointOnTriangle(point, a, b, c)));
            glm::vec3 normal = glm::cross(b - a, c - a);
            if (glm::dot(normal, a - centroid) < 0.0f) normal = -normal;
            if (glm::dot(normal, point - a) > 0.0f) inside = false;
        }
    }
    return inside ? -best : best;
}

SegmentClosestPoints closestPointsOnSegments(const glm::vec3& p0, const glm::vec3& p1,
                                             const glm::vec3& q0, const glm::vec3& q1) {
    // Ericson §5.1.9.
    constexpr float kEpsilon = 1e-9f;
    const glm::vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
    const float a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
    float s = 0.0f, t = 0.0f;
    if (a <= kEpsilon && e <= kEpsilon) {
        s = t = 0.0f;
    } else if (a <= kEpsilon) {
        t = std::clamp(f / e, 0.0f, 1.0f);
    } else {
        const float c = glm::dot(d1, r);
        if (e <= kEpsilon) {
            s = std::clamp(-c / a, 0.0f, 1.0f);
        } else {
            const float b = glm::dot(d1, d2);
            const float denom = a * e - b * b;
            s = denom > kEpsilon * a * e ? std::clamp((b * f - c * e) / denom, 0.0f, 1.0f) : 0.0f;
            t = (b * s + f) / e;
            if (t < 0.0f) {
                t = 0.0f;
                s = std::clamp(-c / a, 0.0f, 1.0f);
            } else if (t > 1.0f) {
                t = 1.0f;
                s = std::clamp((b - c) / a, 0.0f, 1.0f);
            }
        }
    }
    SegmentClosestPoints out;
    out.s = s;
    out.t = t;
    out.onFirst = p0 + d1 * s;
    out.onSecond = q0 + d2 * t;
    out.distance = glm::distance(out.onFirst, out.onSecond);
    return out;
}

float distancePointSegment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b) {
    return closestPointsOnSegments(p, p, a, b).distance;
}

float palmClearanceMm(const HandModel& model, const Capsule& capsule, Side side) {
    // Work in right-hand coordinates: the left hand is the mirror image through y.
    const float ySign = side == Side::Right ? 1.0f : -1.0f;
    const glm::vec3 a{capsule.start.x, capsule.start.y * ySign, capsule.start.z};
    const glm::vec3 b{capsule.end.x, capsule.end.y * ySign, capsule.end.z};
    const HandDimensions& d = model.dimensions;
    // The slab's outline. Only where the bone's axis lies over it is the bone measured: one
    // beside the palm (the thumb along the index in G) lies against its side, which is not
    // sinking into it, and the rectangle is no model of the palm's side near the thumb.
    const float yMin = model.mcpPositionMm[3].y - 0.5f * d.pipWidthMm[3];
    const float yMax = model.mcpPositionMm[0].y + 0.5f * d.pipWidthMm[0];
    const float zMin = d.palmWristZMm, zMax = palmKnuckleZMm(model);
    const auto at = [&](float t) { return a + t * (b - a); };
    // Clip the axis a + t(b - a) to [t0, t1] where g(t) >= 0, for each g linear in t over the
    // part kept so far.
    float t0 = 0.0f, t1 = 1.0f;
    const auto keepWhereNonNegative = [&](const auto& g) {
        if (t0 > t1) return;
        const float g0 = g(at(t0)), g1 = g(at(t1));
        if (g0 < 0.0f && g1 < 0.0f) {
            t1 = -1.0f;
        } else if (g0 < 0.0f || g1 < 0.0f) {
            const float t = t0 + (t1 - t0) * g0 / (g0 - g1);  // where g crosses zero
            (g0 < 0.0f ? t0 : t1) = t;
        }
    };
    keepWhereNonNegative([&](const glm::vec3& p) { return p.y - yMin; });
    keepWhereNonNegative([&](const glm::vec3& p) { return yMax - p.y; });
    keepWhereNonNegative([&](const glm::vec3& p) { return p.z - zMin; });
    keepWhereNonNegative([&](const glm::vec3& p) { return zMax - p.z; });
    // Only the palmar side: a bone behind the back of the hand (dorsal of the slab) is not in
    // the palm. The back surface is linear in z, hence in t, once z is within the slab.
    keepWhereNonNegative([&](const glm::vec3& p) { return p.x - (2.0f * d.palmCentreXMm - palmarSurfaceXMm(model, p.z)); });
    if (t0 > t1) return std::numeric_limits<float>::infinity();
    // Height above the palmar surface is linear in t there too, so its minimum is at an end.
    const auto above = [&](float t) {
        const glm::vec3 p = at(t);
        return p.x - palmarSurfaceXMm(model, p.z);
    };
    return std::min(above(t0), above(t1)) - capsule.radiusMm;
}

float capsuleGap(const Capsule& a, const Capsule& b) {
    return closestPointsOnSegments(a.start, a.end, b.start, b.end).distance - a.radiusMm - b.radiusMm;
}

std::array<Capsule, kBodyCount> boneCapsules(const HandModel& model, const HandPose& pose) {
    std::array<Capsule, kBodyCount> capsules{};
    for (int digit = 0; digit < kDigitCount; ++digit) {
        const int first = firstBodyOf(static_cast<Digit>(digit));
        for (int bone = 0; bone < 3; ++bone) {
            const int b = first + bone;
            Capsule& c = capsules[b];
            c.radiusMm = boneRadiusMm(model, static_cast<Body>(b));
            c.start = pose.bodies[b].position;
            if (bone < 2) {
                c.end = pose.bodies[b + 1].position;
            } else {
                const glm::vec3 toTip = pose.tips[digit] - c.start;
                const float length = glm::length(toTip);
                c.end = c.start + toTip * (std::max(0.0f, length - c.radiusMm) / std::max(length, 1e-6f));
            }
        }
    }
    return capsules;
}

Capsule fingertipSphere(const HandModel& model, const HandPose& pose, Digit digit) {
    const auto capsules = boneCapsules(model, pose);
    const Capsule& distal = capsules[firstBodyOf(digit) + 2];
    return {distal.end, distal.end, distal.radiusMm};
}

BoneGap closestInterDigitGap(const std::array<Capsule, kBodyCount>& capsules, unsigned ignoreDigitPairsMask) {
    BoneGap best{std::numeric_limits<float>::max(), Body::Palm, Body::Palm};
    for (int a = 1; a < kBodyCount; ++a) {
        const int digitA = (a - 1) / 3;
        for (int b = firstBodyOf(static_cast<Digit>(digitA + 1 < kDigitCount ? digitA + 1 : digitA)); b < kBodyCount; ++b) {
            const int digitB = (b - 1) / 3;
            if (digitB == digitA) continue;
            if (ignoreDigitPairsMask & digitPairBit(static_cast<Digit>(digitA), static_cast<Digit>(digitB))) continue;
            const float gap = capsuleGap(capsules[a], capsules[b]);
            if (gap < best.gapMm) best = {gap, static_cast<Body>(a), static_cast<Body>(b)};
        }
    }
    return best;
}

}  // namespace signstim::hand
