#pragma once
// The McDonald kinematic hand (SPEC §1; McDonald et al., "An improved articulated model of
// the human hand").
//
// Overview
// --------
// * 16 rigid bodies: the palm and three bones per digit (thumb: metacarpal, proximal,
//   distal; fingers: proximal, intermediate, distal). `Body` numbers them; `boneName()`
//   gives the VRM humanoid bone name for a side ("rightIndexProximal", "leftHand", ...).
// * Palm frame (SPEC §1.1), millimetres: origin at the base of the palm in the palm plane,
//   +z toward the fingers, +y toward the thumb (right hand), +x out of the palmar surface.
//   Flexion moves fingertips toward +x.
// * Model and data apart (STYLE.md, MuJoCo/Pinocchio): `HandModel` holds everything that is
//   fixed for a hand (dimensions, limits, MCP and CMC positions, radiation and convergence
//   angles) and is built once by `buildHandModel()`. Per frame there are only plain values:
//   `HandControls` (what users and handshape files set) -> `JointAngles` (after the paper's
//   correlations and the limits) -> `HandPose` (16 body transforms + 5 fingertips).
//   The functions between them are pure, allocate nothing and are cheap (> 1 M poses/s).
// * Every body transform is a `RigidTransform` (position in mm + unit quaternion). A body's
//   frame sits at its proximal joint with +z along the bone toward the tip and +x palmar
//   (flexion is a positive rotation about the body's +y).
// * Left hand: the mirror image through the palm's x–z plane (y -> -y), SPEC §1.1. It is
//   applied in exactly one place, `mirrorToLeft()`, which every function taking a `Side`
//   uses. Controls are side-independent: the same handshape gives mirror-image hands.
//
// For a skeleton (the signer avatar): `boneName(side, body)`, `boneParent(body)`,
// `restLocalTransforms(model, side)` (bind pose, local to the parent, palm = root at the
// palm-frame origin) and `localTransforms(pose)` (posed, local to the parent) give
// everything needed to build and pose the 16 hand bones directly.
#include <array>
#include <cstdint>
#include <string_view>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace signstim::hand {

enum class Side : std::uint8_t { Right, Left };

// Digits numbered as in the paper minus one: 0 thumb, 1 index, 2 middle, 3 ring, 4 little.
enum class Digit : std::uint8_t { Thumb = 0, Index, Middle, Ring, Little };
inline constexpr int kDigitCount = 5;
inline constexpr int kFingerCount = 4;  // digits 2–5; finger index 0 = index finger
inline constexpr int kBodyCount = 16;

// Body order: palm, then per digit (thumb..little) its three bones proximal to distal.
// Parent of a bone is the previous bone of the same digit; the first bone's parent is the palm.
enum class Body : std::uint8_t {
    Palm = 0,
    ThumbMetacarpal, ThumbProximal, ThumbDistal,
    IndexProximal, IndexIntermediate, IndexDistal,
    MiddleProximal, MiddleIntermediate, MiddleDistal,
    RingProximal, RingIntermediate, RingDistal,
    LittleProximal, LittleIntermediate, LittleDistal,
};

// First body of a digit (ThumbMetacarpal, IndexProximal, ...); bone k of digit d is
// firstBodyOf(d) + k.
constexpr int firstBodyOf(Digit digit) { return 1 + 3 * static_cast<int>(digit); }
// -1 for the palm.
int boneParent(Body body);
// VRM humanoid bone name: "rightHand", "rightThumbMetacarpal", "leftLittleDistal", ...
std::string_view boneName(Side side, Body body);
// Short digit names "thumb", "index", "middle", "ring", "little".
std::string_view digitName(Digit digit);

// The 16 bones of one hand in Body order, each with its VRM name and its parent's index in
// this array (-1 for the palm, which is the root: "rightHand"/"leftHand").
struct BoneInfo {
    std::string_view name;
    int parent = -1;
};
std::array<BoneInfo, kBodyCount> handBones(Side side);

struct RigidTransform {
    glm::vec3 position{0.0f};                    // mm
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};  // unit quaternion (w, x, y, z)
};
// a ∘ b (apply b, then a): the transform of a child whose local transform is b.
RigidTransform compose(const RigidTransform& a, const RigidTransform& b);
// a⁻¹ ∘ b: b expressed in a's frame.
RigidTransform relative(const RigidTransform& a, const RigidTransform& b);
glm::vec3 transformPoint(const RigidTransform& t, const glm::vec3& p);

// -------------------------------------------------------------------------------------
// Dimensions (SPEC §1.2). Default-constructed = the adult average (HL 190, HB 85);
// `scaledHandDimensions()` scales lengths with HL and widths/spacings with HB.
struct HandDimensions {
    float handLengthMm = 190.0f;
    float handBreadthMm = 85.0f;
    // Bone lengths [digit][bone], mm. Thumb: metacarpal, proximal, distal. Fingers:
    // proximal, intermediate (middle), distal. Buchholz & Armstrong coefficients × HL.
    std::array<std::array<float, 3>, kDigitCount> boneLengthMm{};
    // Finger metacarpal lengths (index..little), used for the MCP height (p₃.z).
    std::array<float, kFingerCount> fingerMetacarpalLengthMm{};
    // Widths at the PIP and DIP (index..little) and MCP centre spacing (index–middle,
    // middle–ring, ring–little); SPEC §1.2 [D], scaled with HB.
    std::array<float, kFingerCount> pipWidthMm{};
    std::array<float, kFingerCount> dipWidthMm{};
    std::array<float, 3> mcpSpacingMm{};
    // Thumb widths at the MCP and IP [D: not in the SPEC; ~thumb-to-index ratio of hand
    // anthropometry, scaled with HB]. Used for contact checks only.
    float thumbMcpWidthMm = 21.0f;
    float thumbIpWidthMm = 19.0f;
    // SPEC §1.3: middle-finger MCP at z = 0.446·HL.
    float middleMcpHeightMm = 0.446f * 190.0f;
    // SPEC §1.3: optional extra drop of the little-finger MCP along −z (real hands 10–15 mm).
    // Default 0 keeps the paper's tangent-curve construction unchanged.
    float littleMcpDropMm = 0.0f;
    // SPEC §1.4: CMC centre ≈ (10, 0.196·HB, 0.073·HL).
    glm::vec3 thumbCmcMm{10.0f, 0.196f * 85.0f, 0.073f * 190.0f};
    // The palm's soft tissue [D: not in the SPEC]: a slab centred at x = palmCentreXMm whose
    // half thickness tapers linearly from the wrist (z = palmWristZMm) to the knuckle line
    // (2 mm past the middle MCP). The avatar's palm mesh and the palm contact check use it.
    float palmCentreXMm = 1.5f;
    float palmWristZMm = -30.0f;
    float palmHalfThicknessWristMm = 15.0f;
    float palmHalfThicknessKnucklesMm = 11.5f;
};
HandDimensions scaledHandDimensions(float handLengthMm = 190.0f, float handBreadthMm = 85.0f);

struct AngleRange {
    float minDeg = 0.0f;
    float maxDeg = 0.0f;
    float clamp(float deg) const { return deg < minDeg ? minDeg : (deg > maxDeg ? maxDeg : deg); }
    bool contains(float deg, float toleranceDeg = 1e-3f) const {
        return deg >= minDeg - toleranceDeg && deg <= maxDeg + toleranceDeg;
    }
};

// Joint limits (SPEC §1.3–§1.4). Every limit is a parameter with the paper's default.
struct HandLimits {
    AngleRange fingerSpread{-25.0f, 30.0f};  // σ, measured after radiation
    AngleRange fingerTwist{-10.0f, 10.0f};   // κ(σ), spread–twist correlation
    AngleRange mcp{-15.0f, 90.0f};           // 15° hyperextension
    AngleRange pip{-20.0f, 120.0f};          // [0,110–120] + 15–25° passive hyperext. [D: 20]
    AngleRange dip{-20.0f, 80.0f};           // [0,80–90] + same hyperextension
    float pipBendMaxDeg = 110.0f;  // PIP reached by Bend = 1 (paper: "90–110°") [D]
    float pipHookMaxDeg = 120.0f;  // PIP reached by Hook = 1; DIP = 2/3 of it = 80° [D]
    AngleRange thumbBend{-25.0f, 120.0f};    // θ: [−25, 90], extended to 120°
    AngleRange thumbSpread{10.0f, 90.0f};    // φ
    AngleRange thumbMcp{-10.0f, 60.0f};
    AngleRange thumbIp{-20.0f, 80.0f};
    // SPEC §1.4 [D]: ψ = ψ₀ + span·r·g, r = clamp((φ − start)/(φmax − start)), g = clamp(θ/full).
    // The span is negative: a pronation, turning the pad toward the fingertips (docs/hand.md).
    float thumbTwistRestDeg = -90.0f;       // ψ₀
    float thumbTwistSpanDeg = -45.0f;
    float thumbTwistStartSpreadDeg = 58.0f;  // 10° + 60 % of the 80° spread range
    float thumbTwistFullBendDeg = 20.0f;
    // CMC rotation R_z(−θ)·R_x(−φ)·R_z(θ)·R_z(ψ): θ and φ swing the metacarpal by the shortest
    // rotation and only ψ rolls it (docs/hand.md). false = SPEC §1.4's literal chain
    // R_z(−θ)·R_x(−φ)·R_z(ψ), whose θ also spins the thumb about its own axis; with
    // thumbTwistSpanDeg = +45 as well, the thumb is exactly SPEC §1.4's.
    bool thumbSpinFreeSwing = true;
};

// Built once. Holds the derived geometry: MCP positions, radiation and convergence twists.
struct HandModel {
    HandDimensions dimensions;
    HandLimits limits;
    std::array<float, kFingerCount> radiationDeg{};    // ρ (SPEC §1.3 [P])
    std::array<float, kFingerCount> convergenceDeg{};  // θ (SPEC §1.3 [D formula])
    std::array<glm::vec3, kFingerCount> mcpPositionMm{};
    // R_x(ρ)·R_z(θ) per finger: the fixed part of each MCP frame.
    std::array<glm::quat, kFingerCount> fingerBaseRotation{};
};
HandModel buildHandModel(const HandDimensions& dimensions = scaledHandDimensions(),
                         const HandLimits& limits = HandLimits{});

// -------------------------------------------------------------------------------------
// Controls (SPEC §1.5). Users never set joint angles directly.
struct FingerControls {
    float spreadDeg = 0.0f;  // σ after radiation; twist κ follows it
    float bend = 0.0f;       // [0,1]: first half MCP 0→90°, second half PIP 0→pipBendMax
    float hook = 0.0f;       // [0,1]: PIP 0→pipHookMax with DIP = 2/3 PIP
};
struct ThumbControls {
    float bendDeg = 0.0f;     // θ: across the palm, about the palm z-axis
    float spreadDeg = 30.0f;  // φ: away from the palm z-axis (twist ψ follows it)
    float mcpDeg = 0.0f;
    float ipDeg = 0.0f;
};
// Default-constructed = the rest (bind) posture: fingers straight, thumb at θ 0, φ 30°.
struct HandControls {
    ThumbControls thumb;
    std::array<FingerControls, kFingerCount> fingers{};  // index, middle, ring, little
};

// Interpolation happens in control space so the correlations hold on every in-between
// frame (SPEC §1.5). t = 0 gives a, t = 1 gives b; linear in every control.
HandControls interpolate(const HandControls& a, const HandControls& b, float t);

// -------------------------------------------------------------------------------------
// Joint angles: the controls after the paper's correlations and the limits, degrees.
struct FingerJointAngles {
    float spreadDeg = 0.0f;  // σ (about the MCP x-axis)
    float twistDeg = 0.0f;   // κ(σ) (about the finger z-axis)
    float mcpDeg = 0.0f;     // flexion, + toward the palm
    float pipDeg = 0.0f;
    float dipDeg = 0.0f;
};
struct ThumbJointAngles {
    float bendDeg = 0.0f;    // θ
    float spreadDeg = 0.0f;  // φ
    float twistDeg = 0.0f;   // ψ
    float mcpDeg = 0.0f;
    float ipDeg = 0.0f;
};
struct JointAngles {
    ThumbJointAngles thumb;
    std::array<FingerJointAngles, kFingerCount> fingers{};
};

// SPEC §1.3 [D]: κ = σ/3 for σ ≥ 0, 0.4·σ for σ < 0 (within ±10° over the spread range).
float fingerTwistDeg(float spreadDeg);
// SPEC §1.4 [D]: thumb twist ψ from spread φ and bend θ.
float thumbTwistDeg(const HandLimits& limits, float spreadDeg, float bendDeg);
// Applies the correlations (spread–twist, bend halves, hook DIP = 2/3 PIP, PIP max rule,
// thumb twist) and clamps every angle to its limit. Out-of-range controls are clamped.
JointAngles jointAngles(const HandModel& model, const HandControls& controls);

// -------------------------------------------------------------------------------------
// Pose: per-frame output, everything in the palm frame (mm), already mirrored for the side.
struct HandPose {
    Side side = Side::Right;
    std::array<RigidTransform, kBodyCount> bodies{};  // indexed by Body; palm = identity
    std::array<glm::vec3, kDigitCount> tips{};        // fingertip points, thumb..little
};

HandPose forwardKinematics(const HandModel& model, const JointAngles& angles, Side side);
HandPose forwardKinematics(const HandModel& model, const HandControls& controls, Side side);

// Posed transforms of each body relative to its parent (palm: its own transform, the
// identity in the palm frame). Suitable for a skeleton's local joint transforms.
std::array<RigidTransform, kBodyCount> localTransforms(const HandPose& pose);
// Local transforms of the rest posture `HandControls{}` (the skeleton's bind pose).
std::array<RigidTransform, kBodyCount> restLocalTransforms(const HandModel& model, Side side);

// The mirror for the left hand (y -> -y, rotations conjugated by the mirror); the one place
// where sides differ. Applying it twice gives the input back.
RigidTransform mirrorToLeft(const RigidTransform& t);
glm::vec3 mirrorToLeft(const glm::vec3& p);

// The palm slab's palmar surface (x, palm frame) at height z: the wrist value below the
// wrist, the knuckle value beyond the knuckle line (HandDimensions::palm*).
float palmarSurfaceXMm(const HandModel& model, float zMm);
// The palm slab's z extent: from the wrist to the knuckle line (2 mm past the middle MCP).
float palmKnuckleZMm(const HandModel& model);

// Radius of a bone's capsule for contact checks, 0 for the palm. [D] fingers: proximal P/2,
// intermediate (P+D)/4, distal D/2; thumb: metacarpal and proximal from the MCP width,
// distal from the IP width.
float boneRadiusMm(const HandModel& model, Body body);
// Length of a bone along its +z (0 for the palm).
float boneLengthMm(const HandModel& model, Body body);

}  // namespace signstim::hand
