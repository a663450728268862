#pragma once
// Contact analysis (SPEC §2.6; van Polanen et al. §7.3.1) and the proximity queries built on
// it: does a sphere touch a hand segment, how far apart are two bones, do two fingers
// interpenetrate. Pure functions on plain values, millimetres.
//
// * `sphereTouchesFacePaper` / `sphereTouchesBoxPaper`: the paper's test, face by face
//   (plane distance S ≤ r and the projected point inside the face by the 360° angle sum).
//   Like the paper it misses contacts on edges and corners only and a centre inside a box.
// * `signedDistanceToBox` / `sphereTouchesBox`: exact point-to-box distance (faces, edges,
//   corners; negative inside) for any convex 8-vertex box, faces split into triangles.
// * `closestPointsOnSegments`: segment-to-segment closest points (Ericson, Real-Time
//   Collision Detection §5.1.9), for two-handed verbs and finger-contact checks.
// * Capsules around the McDonald hand's bones (`boneCapsules`) and the smallest gap between
//   bones of different digits (`closestInterDigitGap`).
#include "hand/hand_model.hpp"

#include <array>

#include <glm/vec3.hpp>

namespace signstim::hand {

// Eight box vertices in the paper's numbering (SPEC §2.5), 0-based here: 0–3 one face
// (1234), 4–7 the opposite face (5678) in the same order.
using BoxVertices = std::array<glm::vec3, 8>;

// SPEC §2.6: faces 1234, 5678, 1265, 4378, 2376, 1485 (0-based vertex indices).
inline constexpr std::array<std::array<int, 4>, 6> kBoxFaces = {{
    {0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 2, 6, 7}, {1, 2, 6, 5}, {0, 3, 7, 4},
}};

// The paper's face test: k = (v₁−v₂)×(v₄−v₁), S = |k·p + k₄|/|k| ≤ r, and the angles
// subtended at the projected point by successive vertices sum to 360° (|Σ − 2π| < tolerance).
bool sphereTouchesFacePaper(const BoxVertices& box, int face, const glm::vec3& centre, float radius,
                            float angleToleranceRad = 1e-3f);
// Any of the six faces (the paper's per-segment rule).
bool sphereTouchesBoxPaper(const BoxVertices& box, const glm::vec3& centre, float radius,
                           float angleToleranceRad = 1e-3f);

// Exact distance from a point to the box surface, negative when the point is inside.
float signedDistanceToBox(const BoxVertices& box, const glm::vec3& point);
// True when the sphere touches or intersects the box (exact, edges and corners included).
inline bool sphereTouchesBox(const BoxVertices& box, const glm::vec3& centre, float radius) {
    return signedDistanceToBox(box, centre) <= radius;
}

struct SegmentClosestPoints {
    float distance = 0.0f;
    float s = 0.0f;  // parameter on the first segment, [0, 1]
    float t = 0.0f;  // parameter on the second segment, [0, 1]
    glm::vec3 onFirst{0.0f};
    glm::vec3 onSecond{0.0f};
};
// Closest points between segments p0–p1 and q0–q1 (degenerate segments allowed).
SegmentClosestPoints closestPointsOnSegments(const glm::vec3& p0, const glm::vec3& p1,
                                             const glm::vec3& q0, const glm::vec3& q1);
float distancePointSegment(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b);

struct Capsule {
    glm::vec3 start{0.0f};
    glm::vec3 end{0.0f};
    float radiusMm = 0.0f;
};
// Surface gap between two capsules: negative when they interpenetrate.
float capsuleGap(const Capsule& a, const Capsule& b);

// One capsule per bone of a posed McDonald hand (index = Body; the palm's is empty, radius
// 0). A bone's capsule runs from its joint to the next joint; the distal bones' capsules
// stop one radius short of the fingertip so that their rounded end is the fingertip [D].
std::array<Capsule, kBodyCount> boneCapsules(const HandModel& model, const HandPose& pose);

// Gap between a capsule and the palm's palmar surface (HandDimensions' palm slab), over the
// part of the capsule's axis that lies over the palm (between the wrist and the knuckle
// line, between the index and little fingers' outer edges, palmar of the slab's back
// surface): negative when the capsule sinks into the palm. +infinity when no part of its
// axis lies over the palm (a bone beside the palm's edge is not measured). The outline is a
// rectangle; the avatar's palm mesh shares the slab's thickness but follows the knuckle arc
// and narrows at the wrist.
// `side` says which hand `capsule` belongs to (the left hand's palm spans -y).
float palmClearanceMm(const HandModel& model, const Capsule& capsule, Side side);

// Centre of a digit's fingertip sphere (the distal capsule's end) and its radius.
Capsule fingertipSphere(const HandModel& model, const HandPose& pose, Digit digit);

struct BoneGap {
    float gapMm = 0.0f;  // negative = interpenetration depth
    Body first = Body::Palm;
    Body second = Body::Palm;
};
// Smallest capsule gap between bones of different digits (the palm excluded). Pairs listed in
// `ignore` (e.g. a thumb–finger contact that the handshape wants) are skipped.
BoneGap closestInterDigitGap(const std::array<Capsule, kBodyCount>& capsules,
                             unsigned ignoreDigitPairsMask = 0);
// Bit for the digit pair (a, b) in `ignoreDigitPairsMask`.
constexpr unsigned digitPairBit(Digit a, Digit b) {
    const int i = static_cast<int>(a) < static_cast<int>(b) ? static_cast<int>(a) : static_cast<int>(b);
    const int j = static_cast<int>(a) < static_cast<int>(b) ? static_cast<int>(b) : static_cast<int>(a);
    return 1u << (i * kDigitCount + j);
}

}  // namespace signstim::hand
