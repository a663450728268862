#include "hand/hand_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace signstim::hand {
namespace {

constexpr float kDegToRad = 0.017453292519943295f;

// Rotations about the frame axes, positive by the right-hand rule. R_y(β) with β > 0 turns
// +z toward +x, i.e. flexes toward the palm (SPEC §1.3: "positive β flexes toward +x").
inline glm::quat rotationX(float deg) {
    const float h = 0.5f * deg * kDegToRad;
    return {std::cos(h), std::sin(h), 0.0f, 0.0f};
}
inline glm::quat rotationY(float deg) {
    const float h = 0.5f * deg * kDegToRad;
    return {std::cos(h), 0.0f, std::sin(h), 0.0f};
}
inline glm::quat rotationZ(float deg) {
    const float h = 0.5f * deg * kDegToRad;
    return {std::cos(h), 0.0f, 0.0f, std::sin(h)};
}
inline glm::vec3 alongZ(const glm::quat& q, float length) { return q * glm::vec3(0.0f, 0.0f, length); }

constexpr std::array<std::string_view, kBodyCount> kRightNames = {
    "rightHand",
    "rightThumbMetacarpal", "rightThumbProximal", "rightThumbDistal",
    "rightIndexProximal", "rightIndexIntermediate", "rightIndexDistal",
    "rightMiddleProximal", "rightMiddleIntermediate", "rightMiddleDistal",
    "rightRingProximal", "rightRingIntermediate", "rightRingDistal",
    "rightLittleProximal", "rightLittleIntermediate", "rightLittleDistal",
};
constexpr std::array<std::string_view, kBodyCount> kLeftNames = {
    "leftHand",
    "leftThumbMetacarpal", "leftThumbProximal", "leftThumbDistal",
    "leftIndexProximal", "leftIndexIntermediate", "leftIndexDistal",
    "leftMiddleProximal", "leftMiddleIntermediate", "leftMiddleDistal",
    "leftRingProximal", "leftRingIntermediate", "leftRingDistal",
    "leftLittleProximal", "leftLittleIntermediate", "leftLittleDistal",
};

float clamp01(float v) { return std::clamp(v, 0.0f, 1.0f); }

}  // namespace

// ---- names and structure -------------------------------------------------------------
int boneParent(Body body) {
    const int b = static_cast<int>(body);
    if (b <= 0) return -1;
    return ((b - 1) % 3 == 0) ? 0 : b - 1;
}

std::string_view boneName(Side side, Body body) {
    const auto b = static_cast<std::size_t>(body);
    if (b >= kBodyCount) throw std::invalid_argument("boneName: body out of range");
    return side == Side::Right ? kRightNames[b] : kLeftNames[b];
}

std::string_view digitName(Digit digit) {
    static constexpr std::array<std::string_view, kDigitCount> names = {"thumb", "index", "middle",
                                                                       "ring", "little"};
    return names.at(static_cast<std::size_t>(digit));
}

std::array<BoneInfo, kBodyCount> handBones(Side side) {
    std::array<BoneInfo, kBodyCount> bones{};
    for (int b = 0; b < kBodyCount; ++b) {
        bones[b] = {boneName(side, static_cast<Body>(b)), boneParent(static_cast<Body>(b))};
    }
    return bones;
}

// ---- rigid transforms ----------------------------------------------------------------
RigidTransform compose(const RigidTransform& a, const RigidTransform& b) {
    return {a.position + a.rotation * b.position, a.rotation * b.rotation};
}

RigidTransform relative(const RigidTransform& a, const RigidTransform& b) {
    const glm::quat inverse = glm::conjugate(a.rotation);
    return {inverse * (b.position - a.position), glm::normalize(inverse * b.rotation)};
}

glm::vec3 transformPoint(const RigidTransform& t, const glm::vec3& p) {
    return t.position + t.rotation * p;
}

// SPEC §1.1: the left hand is the mirror image through the palm's x–z plane. Conjugating a
// rotation by S = diag(1, −1, 1) flips the axis' y and the angle's sign: (w,x,y,z) → (w,−x,y,−z).
RigidTransform mirrorToLeft(const RigidTransform& t) {
    return {mirrorToLeft(t.position),
            glm::quat(t.rotation.w, -t.rotation.x, t.rotation.y, -t.rotation.z)};
}
glm::vec3 mirrorToLeft(const glm::vec3& p) { return {p.x, -p.y, p.z}; }

// ---- dimensions and model ------------------------------------------------------------
HandDimensions scaledHandDimensions(float handLengthMm, float handBreadthMm) {
    if (!(handLengthMm > 0.0f) || !(handBreadthMm > 0.0f)) {
        throw std::invalid_argument("scaledHandDimensions: hand length and breadth must be > 0");
    }
    HandDimensions d;
    d.handLengthMm = handLengthMm;
    d.handBreadthMm = handBreadthMm;
    // SPEC §1.2: Buchholz & Armstrong (1992) bone-length coefficients × HL.
    constexpr std::array<std::array<float, 3>, kDigitCount> lengthCoefficients = {{
        {0.251f, 0.196f, 0.158f},  // thumb: metacarpal, proximal, distal
        {0.265f, 0.143f, 0.097f},  // index: proximal, middle, distal
        {0.277f, 0.170f, 0.108f},  // middle
        {0.259f, 0.165f, 0.107f},  // ring
        {0.206f, 0.117f, 0.093f},  // little
    }};
    constexpr std::array<float, kFingerCount> metacarpalCoefficients = {0.374f, 0.373f, 0.336f, 0.295f};
    for (int digit = 0; digit < kDigitCount; ++digit) {
        for (int bone = 0; bone < 3; ++bone) {
            d.boneLengthMm[digit][bone] = lengthCoefficients[digit][bone] * handLengthMm;
        }
    }
    for (int f = 0; f < kFingerCount; ++f) {
        d.fingerMetacarpalLengthMm[f] = metacarpalCoefficients[f] * handLengthMm;
    }
    // SPEC §1.2 [D]: widths and MCP spacing at HB = 85 mm, scaled with HB.
    const float breadthScale = handBreadthMm / 85.0f;
    constexpr std::array<float, kFingerCount> pip = {20.0f, 20.0f, 19.0f, 17.0f};
    constexpr std::array<float, kFingerCount> dip = {17.5f, 17.5f, 16.5f, 14.5f};
    constexpr std::array<float, 3> spacing = {22.0f, 21.0f, 19.5f};
    for (int f = 0; f < kFingerCount; ++f) {
        d.pipWidthMm[f] = pip[f] * breadthScale;
        d.dipWidthMm[f] = dip[f] * breadthScale;
    }
    for (int i = 0; i < 3; ++i) d.mcpSpacingMm[i] = spacing[i] * breadthScale;
    d.thumbMcpWidthMm = 21.0f * breadthScale;
    d.thumbIpWidthMm = 19.0f * breadthScale;
    d.middleMcpHeightMm = 0.446f * handLengthMm;  // SPEC §1.3
    d.littleMcpDropMm = 0.0f;
    d.thumbCmcMm = {10.0f * breadthScale, 0.196f * handBreadthMm, 0.073f * handLengthMm};  // SPEC §1.4
    d.palmCentreXMm = 1.5f * breadthScale;
    d.palmWristZMm = -30.0f * handLengthMm / 190.0f;
    d.palmHalfThicknessWristMm = 15.0f * breadthScale;
    d.palmHalfThicknessKnucklesMm = 11.5f * breadthScale;
    return d;
}

HandModel buildHandModel(const HandDimensions& dimensions, const HandLimits& limits) {
    for (const auto& digit : dimensions.boneLengthMm) {
        for (float length : digit) {
            if (!(length > 0.0f)) throw std::invalid_argument("buildHandModel: bone lengths must be > 0");
        }
    }
    HandModel model;
    model.dimensions = dimensions;
    model.limits = limits;
    model.radiationDeg = {-8.0f, 0.0f, 4.0f, 14.0f};  // SPEC §1.3 [P]: metacarpal radiation ρ

    // SPEC §1.3 [D formula]: convergence Δᵢ between neighbours so that fingers bent 90° at
    // the MCP do not overlap at the PIP nor the DIP; θ₃ = 0.
    const auto& len = dimensions.boneLengthMm;
    std::array<float, 3> convergenceRad{};
    for (int i = 0; i < 3; ++i) {
        const int a = i + 1, b = i + 2;  // digits of fingers i, i+1
        const float sP = 0.5f * (len[a][0] + len[b][0]);
        const float sD = 0.5f * (len[a][0] + len[a][1] + len[b][0] + len[b][1]);
        const float gapPip = dimensions.mcpSpacingMm[i] - 0.5f * (dimensions.pipWidthMm[i] + dimensions.pipWidthMm[i + 1]);
        const float gapDip = dimensions.mcpSpacingMm[i] - 0.5f * (dimensions.dipWidthMm[i] + dimensions.dipWidthMm[i + 1]);
        convergenceRad[i] = std::max(0.0f, std::min(gapPip / sP, gapDip / sD));
    }
    constexpr float kRadToDeg = 1.0f / kDegToRad;
    model.convergenceDeg = {-convergenceRad[0] * kRadToDeg, 0.0f, convergenceRad[1] * kRadToDeg,
                            (convergenceRad[1] + convergenceRad[2]) * kRadToDeg};

    for (int f = 0; f < kFingerCount; ++f) {
        model.fingerBaseRotation[f] = rotationX(model.radiationDeg[f]) * rotationZ(model.convergenceDeg[f]);
    }
    // SPEC §1.3 [D construction]: MCPs on a curve tangent to the twisted y-axes, keeping Bᵢ.
    std::array<glm::vec3, kFingerCount> twistedY{};
    for (int f = 0; f < kFingerCount; ++f) twistedY[f] = model.fingerBaseRotation[f] * glm::vec3(0, 1, 0);
    auto chord = [&](int i, int j) { return glm::normalize(twistedY[i] + twistedY[j]); };
    const auto& spacing = dimensions.mcpSpacingMm;
    model.mcpPositionMm[1] = {0.0f, 0.0f, dimensions.middleMcpHeightMm};
    model.mcpPositionMm[0] = model.mcpPositionMm[1] + spacing[0] * chord(0, 1);
    model.mcpPositionMm[2] = model.mcpPositionMm[1] - spacing[1] * chord(1, 2);
    model.mcpPositionMm[3] = model.mcpPositionMm[2] - spacing[2] * chord(2, 3) -
                             glm::vec3(0.0f, 0.0f, dimensions.littleMcpDropMm);
    return model;
}

// ---- controls -> joint angles --------------------------------------------------------
HandControls interpolate(const HandControls& a, const HandControls& b, float t) {
    auto mix = [t](float x, float y) { return x + (y - x) * t; };
    HandControls out;
    out.thumb.bendDeg = mix(a.thumb.bendDeg, b.thumb.bendDeg);
    out.thumb.spreadDeg = mix(a.thumb.spreadDeg, b.thumb.spreadDeg);
    out.thumb.mcpDeg = mix(a.thumb.mcpDeg, b.thumb.mcpDeg);
    out.thumb.ipDeg = mix(a.thumb.ipDeg, b.thumb.ipDeg);
    for (int f = 0; f < kFingerCount; ++f) {
        out.fingers[f].spreadDeg = mix(a.fingers[f].spreadDeg, b.fingers[f].spreadDeg);
        out.fingers[f].bend = mix(a.fingers[f].bend, b.fingers[f].bend);
        out.fingers[f].hook = mix(a.fingers[f].hook, b.fingers[f].hook);
    }
    return out;
}

float fingerTwistDeg(float spreadDeg) {
    // SPEC §1.3 [D]: κ = σ/3 (σ ≥ 0), 0.4·σ (σ < 0): ±10° at the spread limits.
    return spreadDeg >= 0.0f ? spreadDeg / 3.0f : 0.4f * spreadDeg;
}

float thumbTwistDeg(const HandLimits& limits, float spreadDeg, float bendDeg) {
    // SPEC §1.4 [D]: twist starts at ~60 % of the spread range, spans 45°, and is scaled
    // down when the bend θ is below 20°.
    const float spreadFraction = clamp01((spreadDeg - limits.thumbTwistStartSpreadDeg) /
                                         (limits.thumbSpread.maxDeg - limits.thumbTwistStartSpreadDeg));
    const float bendFraction = clamp01(bendDeg / limits.thumbTwistFullBendDeg);
    return limits.thumbTwistRestDeg + limits.thumbTwistSpanDeg * spreadFraction * bendFraction;
}

JointAngles jointAngles(const HandModel& model, const HandControls& controls) {
    const HandLimits& lim = model.limits;
    JointAngles out;
    for (int f = 0; f < kFingerCount; ++f) {
        const FingerControls& c = controls.fingers[f];
        FingerJointAngles& j = out.fingers[f];
        j.spreadDeg = lim.fingerSpread.clamp(c.spreadDeg);
        j.twistDeg = lim.fingerTwist.clamp(fingerTwistDeg(j.spreadDeg));
        // SPEC §1.5: the first half of Bend moves only the MCP (0→90°), the second half only
        // the PIP (0→pipBendMax). Negative bend hyperextends the MCP, clamped [D].
        const float bend = std::min(c.bend, 1.0f);
        j.mcpDeg = lim.mcp.clamp(std::min(bend, 0.5f) * 2.0f * 90.0f);
        // SPEC §1.5: Hook bends PIP and DIP together with DIP = 2/3 PIP.
        const float pipFromHook = lim.pip.clamp(std::min(c.hook, 1.0f) * lim.pipHookMaxDeg);
        j.dipDeg = lim.dip.clamp(pipFromHook * (2.0f / 3.0f));
        // SPEC §1.5: PIP = max(PIP from bend, PIP from hook). Bend only specifies the PIP in
        // its second half; below that a negative hook may hyperextend the PIP [D].
        if (bend > 0.5f) {
            const float pipFromBend = (bend - 0.5f) * 2.0f * lim.pipBendMaxDeg;
            j.pipDeg = lim.pip.clamp(std::max(pipFromBend, pipFromHook));
        } else {
            j.pipDeg = pipFromHook;
        }
    }
    ThumbJointAngles& t = out.thumb;
    t.bendDeg = lim.thumbBend.clamp(controls.thumb.bendDeg);
    t.spreadDeg = lim.thumbSpread.clamp(controls.thumb.spreadDeg);
    t.twistDeg = thumbTwistDeg(lim, t.spreadDeg, t.bendDeg);
    t.mcpDeg = lim.thumbMcp.clamp(controls.thumb.mcpDeg);
    t.ipDeg = lim.thumbIp.clamp(controls.thumb.ipDeg);
    return out;
}

// ---- forward kinematics --------------------------------------------------------------
HandPose forwardKinematics(const HandModel& model, const JointAngles& angles, Side side) {
    HandPose pose;
    pose.side = side;
    const auto& len = model.dimensions.boneLengthMm;

    // SPEC §1.4: T(c)·R_z(−θ)R_x(−φ)R_z(ψ)·T(0,0,l_mc)R_y(β_MCP)·T(0,0,l_prox)R_y(β_IP)·T(0,0,l_dist),
    // with R_z(θ) before R_z(ψ) when the swing is spin-free (HandLimits::thumbSpinFreeSwing).
    {
        const ThumbJointAngles& t = angles.thumb;
        RigidTransform& metacarpal = pose.bodies[static_cast<int>(Body::ThumbMetacarpal)];
        metacarpal.position = model.dimensions.thumbCmcMm;
        metacarpal.rotation = rotationZ(-t.bendDeg) * rotationX(-t.spreadDeg) *
                              rotationZ((model.limits.thumbSpinFreeSwing ? t.bendDeg : 0.0f) + t.twistDeg);
        RigidTransform& proximal = pose.bodies[static_cast<int>(Body::ThumbProximal)];
        proximal.position = metacarpal.position + alongZ(metacarpal.rotation, len[0][0]);
        proximal.rotation = metacarpal.rotation * rotationY(t.mcpDeg);
        RigidTransform& distal = pose.bodies[static_cast<int>(Body::ThumbDistal)];
        distal.position = proximal.position + alongZ(proximal.rotation, len[0][1]);
        distal.rotation = proximal.rotation * rotationY(t.ipDeg);
        pose.tips[0] = distal.position + alongZ(distal.rotation, len[0][2]);
    }
    // SPEC §1.3 [P order: spread before bend]:
    // T(pᵢ)·R_x(ρᵢ)R_z(θᵢ)·R_x(σᵢ)R_z(κ(σᵢ))R_y(β_MCP)·T(0,0,l_prox)R_y(β_PIP)·T(0,0,l_mid)R_y(β_DIP)·T(0,0,l_dist)
    for (int f = 0; f < kFingerCount; ++f) {
        const FingerJointAngles& j = angles.fingers[f];
        const int digit = f + 1;
        const int first = firstBodyOf(static_cast<Digit>(digit));
        RigidTransform& proximal = pose.bodies[first];
        proximal.position = model.mcpPositionMm[f];
        proximal.rotation = model.fingerBaseRotation[f] * rotationX(j.spreadDeg) *
                            rotationZ(j.twistDeg) * rotationY(j.mcpDeg);
        RigidTransform& intermediate = pose.bodies[first + 1];
        intermediate.position = proximal.position + alongZ(proximal.rotation, len[digit][0]);
        intermediate.rotation = proximal.rotation * rotationY(j.pipDeg);
        RigidTransform& distal = pose.bodies[first + 2];
        distal.position = intermediate.position + alongZ(intermediate.rotation, len[digit][1]);
        distal.rotation = intermediate.rotation * rotationY(j.dipDeg);
        pose.tips[digit] = distal.position + alongZ(distal.rotation, len[digit][2]);
    }
    if (side == Side::Left) {
        for (auto& body : pose.bodies) body = mirrorToLeft(body);
        for (auto& tip : pose.tips) tip = mirrorToLeft(tip);
    }
    return pose;
}

HandPose forwardKinematics(const HandModel& model, const HandControls& controls, Side side) {
    return forwardKinematics(model, jointAngles(model, controls), side);
}

std::array<RigidTransform, kBodyCount> localTransforms(const HandPose& pose) {
    std::array<RigidTransform, kBodyCount> local{};
    local[0] = pose.bodies[0];
    for (int b = 1; b < kBodyCount; ++b) {
        local[b] = relative(pose.bodies[boneParent(static_cast<Body>(b))], pose.bodies[b]);
    }
    return local;
}

std::array<RigidTransform, kBodyCount> restLocalTransforms(const HandModel& model, Side side) {
    return localTransforms(forwardKinematics(model, HandControls{}, side));
}

float boneLengthMm(const HandModel& model, Body body) {
    const int b = static_cast<int>(body);
    if (b <= 0 || b >= kBodyCount) return 0.0f;
    return model.dimensions.boneLengthMm[(b - 1) / 3][(b - 1) % 3];
}

float palmKnuckleZMm(const HandModel& model) { return model.mcpPositionMm[1].z + 2.0f; }

float palmarSurfaceXMm(const HandModel& model, float zMm) {
    const HandDimensions& d = model.dimensions;
    const float s = clamp01((zMm - d.palmWristZMm) / (palmKnuckleZMm(model) - d.palmWristZMm));
    return d.palmCentreXMm + d.palmHalfThicknessWristMm +
           (d.palmHalfThicknessKnucklesMm - d.palmHalfThicknessWristMm) * s;
}

float boneRadiusMm(const HandModel& model, Body body) {
    const int b = static_cast<int>(body);
    if (b <= 0 || b >= kBodyCount) return 0.0f;
    const int digit = (b - 1) / 3, bone = (b - 1) % 3;
    const HandDimensions& d = model.dimensions;
    if (digit == 0) {
        if (bone == 0) return 0.5f * d.thumbMcpWidthMm;
        if (bone == 1) return 0.25f * (d.thumbMcpWidthMm + d.thumbIpWidthMm);
        return 0.5f * d.thumbIpWidthMm;
    }
    const int f = digit - 1;
    if (bone == 0) return 0.5f * d.pipWidthMm[f];
    if (bone == 1) return 0.25f * (d.pipWidthMm[f] + d.dipWidthMm[f]);
    return 0.5f * d.dipWidthMm[f];
}

}  // namespace signstim::hand
