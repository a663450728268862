#include "hand/arm_ik.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace signstim::hand {
namespace {

constexpr float kPi = 3.14159265358979323846f;
constexpr float kDeg = kPi / 180.0f;

const glm::vec3 kUp{0.0f, 1.0f, 0.0f};
const glm::vec3 kForward{0.0f, 0.0f, 1.0f};

// +1 for the right arm, -1 for the left: converts the mirrored frames' angles to anatomy.
float anatomicalSign(Side side) { return side == Side::Right ? 1.0f : -1.0f; }
// Unit vector from the body midline toward this arm's shoulder (+x is the signer's left).
glm::vec3 lateral(Side side) { return side == Side::Right ? glm::vec3(-1, 0, 0) : glm::vec3(1, 0, 0); }

glm::quat frameFromAxes(const glm::vec3& x, const glm::vec3& z) {
    const glm::vec3 y = glm::cross(z, x);
    return glm::normalize(glm::quat_cast(glm::mat3(x, y, z)));
}

float wrapPi(float a) {
    while (a > kPi) a -= 2.0f * kPi;
    while (a < -kPi) a += 2.0f * kPi;
    return a;
}

float clampf(float v, float lo, float hi) { return std::min(std::max(v, lo), hi); }

float smoothstep(float edge0, float edge1, float x) {
    const float t = clampf((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// Squared normalised distance of an angle from 0 within its range, plus a steep penalty
// beyond the range. Used to keep the wrist comfortable.
float comfort(float deg, const AngleRange& range) {
    const float half = deg >= 0.0f ? std::max(range.maxDeg, 1.0f) : std::max(-range.minDeg, 1.0f);
    const float normalised = deg / half;
    const float excess = std::max(0.0f, deg - range.maxDeg) + std::max(0.0f, range.minDeg - deg);
    return normalised * normalised + 3.0f * (excess / 10.0f) * (excess / 10.0f);
}

float rangeExcessDeg(float deg, const AngleRange& range) {
    return std::max(0.0f, deg - range.maxDeg) + std::max(0.0f, range.minDeg - deg);
}

// Everything that depends on the swivel angle.
struct Candidate {
    glm::vec3 elbowDirection;
    glm::vec3 elbowMm;
    glm::quat upperArm, forearm;
    float elevationDeg, planeDeg, shoulderExcessDeg;
    WristAngles wrist;
    float cost;
};

struct Geometry {
    const ArmModel* arm;
    const ArmTarget* target;
    const ArmSolveOptions* options;
    glm::vec3 shoulder, wrist, axis, ref0, ref1;
    float cosAlpha, sinAlpha;  // angle at the shoulder between the axis and the upper arm
};

// Issue 21: the elbow never above its shoulder joint unless the hand is above the head, and then
// no higher than the wrist is above the top of the head (ArmModel::elbowRiseWristAboveShoulderMm;
// until 2026-11-27 the cap was the wrist itself, and a hand at the face lifted the elbow up to
// 236 mm over the shoulder: BOY). The elbow's height is h0 + A·cos(swivel − φ) on its circle about
// the shoulder–wrist axis; the swivels that keep it at or below the cap are an arc, and
// a swivel outside it is moved to the arc's nearer end (or to the lowest swivel where no swivel
// is low enough). Continuous in the swivel and the target, so a pose stays a continuous
// function of time.
float capElbowHeight(const Geometry& g, float swivel) {
    const float a = g.arm->upperArmLengthMm;
    const float h0 = a * g.cosAlpha * g.axis.y;                // height above the shoulder, axis part
    const float c = a * g.sinAlpha * g.ref0.y, s = a * g.sinAlpha * g.ref1.y;  // h = h0 + c·cos + s·sin
    const float amplitude = std::sqrt(c * c + s * s);
    if (amplitude < 1e-3f) return swivel;
    const float cap = std::max(0.0f, g.wrist.y - g.shoulder.y - g.arm->elbowRiseWristAboveShoulderMm);
    const float phi = std::atan2(s, c);  // the highest swivel
    const float ratio = (cap - h0) / amplitude;
    if (ratio >= 1.0f) return swivel;  // never above the cap
    const float halfForbidden = std::acos(std::max(-1.0f, ratio));
    const float offset = wrapPi(swivel - phi);
    if (std::fabs(offset) >= halfForbidden) return swivel;
    return phi + (offset >= 0.0f ? halfForbidden : -halfForbidden);
}

// `frames`: also the upper arm's frame, which the cost does not read (the swivel search asks
// for the cost alone; the chosen swivel is evaluated again in full).
Candidate evaluate(const Geometry& g, float swivel, bool frames = true) {
    const ArmModel& arm = *g.arm;
    Candidate c{};
    swivel = capElbowHeight(g, swivel);
    c.elbowDirection = std::cos(swivel) * g.ref0 + std::sin(swivel) * g.ref1;
    const glm::vec3 upperDir = g.cosAlpha * g.axis + g.sinAlpha * c.elbowDirection;
    // The forearm folds toward the front of the upper arm: in the arm plane, perpendicular
    // to the upper arm, on the wrist's side.
    const glm::vec3 anterior = g.sinAlpha * g.axis - g.cosAlpha * c.elbowDirection;
    const glm::vec3 hinge = glm::normalize(glm::cross(upperDir, anterior));
    const glm::vec3 palmar = (arm.side == Side::Right ? -1.0f : 1.0f) * hinge;
    c.elbowMm = g.shoulder + arm.upperArmLengthMm * upperDir;
    glm::vec3 forearmDir = g.wrist - c.elbowMm;
    const float forearmLen = glm::length(forearmDir);
    forearmDir = forearmLen > 1e-4f ? forearmDir / forearmLen : upperDir;
    if (frames) c.upperArm = frameFromAxes(palmar, upperDir);
    c.forearm = frameFromAxes(palmar, forearmDir);

    const glm::vec3 side = lateral(arm.side);
    c.elevationDeg = std::acos(clampf(-upperDir.y, -1.0f, 1.0f)) / kDeg;
    c.planeDeg = std::atan2(glm::dot(upperDir, kForward), glm::dot(upperDir, side)) / kDeg;
    const float raised = std::sin(c.elevationDeg * kDeg);
    c.shoulderExcessDeg = rangeExcessDeg(c.elevationDeg, arm.limits.shoulderElevation) +
                          raised * rangeExcessDeg(c.planeDeg, arm.limits.shoulderPlane);

    c.wrist = wristAngles(arm.side, c.forearm, g.target->handRotation);
    const float wristCost = comfort(c.wrist.supinationDeg, arm.limits.supination) +
                            comfort(c.wrist.flexionDeg, arm.limits.wristFlexion) +
                            comfort(c.wrist.ulnarDeviationDeg, arm.limits.wristUlnarDeviation);
    const float s = wrapPi(swivel);
    const float shoulderRad = c.shoulderExcessDeg * kDeg;
    // Elbow inside the torso: how far it is short of the minimum lateral distance, faded out
    // over 60 mm in front of the chest.
    const float inFront = smoothstep(arm.torsoFrontMm, arm.torsoFrontMm + 60.0f, c.elbowMm.z);
    const float torsoDeficit =
        (1.0f - inFront) * std::max(0.0f, arm.minElbowLateralMm - glm::dot(c.elbowMm, side)) / 50.0f;
    c.cost = g.options->poleWeight * s * s + g.options->wristComfortWeight * wristCost +
             g.options->shoulderLimitWeight * shoulderRad * shoulderRad +
             g.options->torsoWeight * torsoDeficit * torsoDeficit;
    return c;
}

// Grid then golden-section refinement of the swivel on [lo, hi] (radians).
float searchSwivel(const Geometry& g, float lo, float hi, float gridStep) {
    float best = lo, bestCost = evaluate(g, lo, false).cost;
    const int steps = std::max(1, static_cast<int>(std::ceil((hi - lo) / gridStep)));
    for (int i = 1; i <= steps; ++i) {
        const float s = lo + (hi - lo) * static_cast<float>(i) / static_cast<float>(steps);
        const float cost = evaluate(g, s, false).cost;
        if (cost < bestCost) { bestCost = cost; best = s; }
    }
    float a = std::max(lo, best - gridStep), b = std::min(hi, best + gridStep);
    const float ratio = 0.6180339887f;
    float x1 = b - ratio * (b - a), x2 = a + ratio * (b - a);
    float f1 = evaluate(g, x1, false).cost, f2 = evaluate(g, x2, false).cost;
    for (int i = 0; i < 24; ++i) {
        if (f1 < f2) { b = x2; x2 = x1; f2 = f1; x1 = b - ratio * (b - a); f1 = evaluate(g, x1, false).cost; }
        else { a = x1; x1 = x2; f1 = f2; x2 = a + ratio * (b - a); f2 = evaluate(g, x2, false).cost; }
    }
    const float refined = 0.5f * (a + b);
    return evaluate(g, refined, false).cost < bestCost ? refined : best;
}

// Where the wrist goes: the shoulder–wrist axis and distance, the target's clamped to what the
// elbow's flexion limits allow. Independent of the swivel (solveArm and reachedWristMm share it).
struct Reach {
    glm::vec3 axis, wristMm;
    float distanceMm;
};

Reach reachOf(const ArmModel& arm, const ArmTarget& target) {
    const float a = arm.upperArmLengthMm, b = arm.forearmLengthMm;
    if (!(a > 0.0f) || !(b > 0.0f)) throw std::invalid_argument("solveArm: segment lengths must be > 0");
    // Reach: the shoulder–wrist distance d(flexion) = sqrt(a² + b² + 2ab·cos flexion).
    const auto distanceAt = [&](float flexDeg) {
        return std::sqrt(a * a + b * b + 2.0f * a * b * std::cos(flexDeg * kDeg));
    };
    const float dMax = distanceAt(arm.limits.elbowFlexion.minDeg);
    const float dMin = distanceAt(arm.limits.elbowFlexion.maxDeg);
    const glm::vec3 toTarget = target.wristMm - arm.shoulderMm;
    const float dTarget = glm::length(toTarget);
    Reach reach{};
    reach.axis = dTarget > 1e-3f ? toTarget / dTarget : glm::vec3(0, -1, 0);
    reach.distanceMm = clampf(dTarget, dMin, dMax);
    reach.wristMm = arm.shoulderMm + reach.distanceMm * reach.axis;
    return reach;
}

}  // namespace

glm::vec3 reachedWristMm(const ArmModel& arm, const ArmTarget& target) { return reachOf(arm, target).wristMm; }

ArmModel defaultArmModel(Side side) {
    ArmModel arm;
    arm.side = side;
    if (side == Side::Left) arm.shoulderMm.x = -arm.shoulderMm.x;
    return arm;
}

glm::quat restFrame(Side side) {
    // T-pose, palm down, thumb forward: z along the arm (outward), x palmar (down).
    return frameFromAxes(glm::vec3(0, -1, 0), lateral(side));
}

float rotationAngleDeg(const glm::quat& a, const glm::quat& b) {
    const float d = std::min(1.0f, std::fabs(glm::dot(glm::normalize(a), glm::normalize(b))));
    return 2.0f * std::acos(d) / kDeg;
}

WristAngles wristAngles(Side side, const glm::quat& forearm, const glm::quat& hand) {
    // hand = forearm · R_z(τ) · R_y(f) · R_x(d)  (pronation in the forearm, then the wrist's
    // flexion and deviation).
    const glm::mat3 rel = glm::mat3_cast(glm::inverse(forearm) * hand);
    const glm::vec3 v = rel[0];
    const float tau = std::atan2(v.y, v.x);
    const glm::mat3 unTwist = glm::mat3_cast(glm::angleAxis(-tau, glm::vec3(0, 0, 1)));
    const glm::vec3 vt = unTwist * v;
    const float flex = std::atan2(-vt.z, vt.x);
    const glm::mat3 rest =
        glm::mat3_cast(glm::angleAxis(-flex, glm::vec3(0, 1, 0))) * unTwist * rel;
    const float dev = std::atan2(rest[1].z, rest[1].y);
    const float s = anatomicalSign(side);
    return {s * tau / kDeg, flex / kDeg, s * dev / kDeg};
}

glm::quat handFrame(Side side, const glm::quat& forearm, const WristAngles& angles) {
    const float s = anatomicalSign(side);
    return glm::normalize(forearm *
                          glm::angleAxis(s * angles.supinationDeg * kDeg, glm::vec3(0, 0, 1)) *
                          glm::angleAxis(angles.flexionDeg * kDeg, glm::vec3(0, 1, 0)) *
                          glm::angleAxis(s * angles.ulnarDeviationDeg * kDeg, glm::vec3(1, 0, 0)));
}

ArmPose solveArm(const ArmModel& arm, const ArmTarget& target, const ArmSolveOptions& options) {
    const float a = arm.upperArmLengthMm, b = arm.forearmLengthMm;
    Geometry g{};
    g.arm = &arm;
    g.target = &target;
    g.options = &options;
    g.shoulder = arm.shoulderMm;

    const Reach reach = reachOf(arm, target);
    g.axis = reach.axis;
    const float d = reach.distanceMm;
    g.wrist = reach.wristMm;
    g.cosAlpha = clampf((a * a + d * d - b * b) / (2.0f * a * d), -1.0f, 1.0f);
    g.sinAlpha = std::sqrt(std::max(0.0f, 1.0f - g.cosAlpha * g.cosAlpha));

    // The natural pole [D]: down, outward and back, more outward as the wrist rises.
    const glm::vec3 side = lateral(arm.side);
    const float rise = smoothstep(-50.0f, 150.0f, target.wristMm.y - g.shoulder.y);
    glm::vec3 pole = -kUp + (arm.poleOutward + arm.poleOutwardWhenHigh * rise) * side -
                     arm.poleBackward * kForward;
    pole = glm::normalize(pole);
    glm::vec3 ref = pole - glm::dot(pole, g.axis) * g.axis;
    if (glm::length(ref) < 1e-3f) {  // wrist straight along the pole: fall back to "back"
        ref = -kForward - glm::dot(-kForward, g.axis) * g.axis;
    }
    g.ref0 = glm::normalize(ref);
    g.ref1 = glm::cross(g.axis, g.ref0);

    float swivel = 0.0f;
    bool windowed = false;
    if (options.previousElbowDirection) {
        const glm::vec3 prev = *options.previousElbowDirection;
        const glm::vec3 inPlane = prev - glm::dot(prev, g.axis) * g.axis;
        if (glm::length(inPlane) > 1e-3f) {
            const float previous = std::atan2(glm::dot(inPlane, g.ref1), glm::dot(inPlane, g.ref0));
            if (options.maxSwivelStepDeg <= 0.0f) {
                // Follow the hint: the elbow where the given direction lies about the axis, no
                // search (a search's argmin can change basin between neighbouring instants).
                swivel = previous;
            } else {
                const float stepDeg = std::max(options.maxSwivelStepDeg, 0.5f);
                float yieldDeg = 0.0f;
                if (options.hintYieldPerWristDeg > 0.0f) {  // off by default: no evaluation spent on it
                    const WristAngles atHint = evaluate(g, previous, false).wrist;
                    const float excessDeg = rangeExcessDeg(atHint.supinationDeg, arm.limits.supination) +
                                            rangeExcessDeg(atHint.flexionDeg, arm.limits.wristFlexion) +
                                            rangeExcessDeg(atHint.ulnarDeviationDeg, arm.limits.wristUlnarDeviation);
                    // [D] The first 15° beyond the wrist limits do not widen it: the hint keeps the
                    // elbow where the wrist is only a little short (wider, the hands of story 06's
                    // IX -> EMAIL met 14 mm deep at the transition).
                    yieldDeg = options.hintYieldPerWristDeg * std::max(0.0f, excessDeg - 15.0f);
                }
                const float step = std::min(stepDeg + yieldDeg, std::max(stepDeg, options.swivelWindowDeg)) * kDeg;
                swivel = searchSwivel(g, previous - step, previous + step, 1.0f * kDeg);
            }
            windowed = true;
        }
    }
    if (!windowed) {
        const float window = std::clamp(options.swivelWindowDeg, 1.0f, 180.0f) * kDeg;
        swivel = searchSwivel(g, -window, window, 3.0f * kDeg);
    }
    swivel = capElbowHeight(g, swivel);

    const Candidate c = evaluate(g, swivel);
    ArmPose pose;
    pose.shoulderMm = g.shoulder;
    pose.elbowMm = c.elbowMm;
    pose.wristMm = g.wrist;
    pose.upperArm = c.upperArm;
    pose.forearm = c.forearm;
    pose.elbowDirection = c.elbowDirection;
    pose.swivelDeg = wrapPi(swivel) / kDeg;
    const float cosElbow = clampf((a * a + b * b - d * d) / (2.0f * a * b), -1.0f, 1.0f);
    pose.elbowFlexionDeg = 180.0f - std::acos(cosElbow) / kDeg;
    pose.shoulderElevationDeg = c.elevationDeg;
    pose.shoulderPlaneDeg = c.planeDeg;
    pose.shoulderLimited = c.shoulderExcessDeg > 0.5f;

    WristAngles clamped{arm.limits.supination.clamp(c.wrist.supinationDeg),
                        arm.limits.wristFlexion.clamp(c.wrist.flexionDeg),
                        arm.limits.wristUlnarDeviation.clamp(c.wrist.ulnarDeviationDeg)};
    pose.supinationDeg = clamped.supinationDeg;
    pose.wristFlexionDeg = clamped.flexionDeg;
    pose.wristUlnarDeviationDeg = clamped.ulnarDeviationDeg;
    pose.hand = handFrame(arm.side, c.forearm, clamped);
    pose.wristLimited = std::fabs(clamped.supinationDeg - c.wrist.supinationDeg) > 1e-3f ||
                        std::fabs(clamped.flexionDeg - c.wrist.flexionDeg) > 1e-3f ||
                        std::fabs(clamped.ulnarDeviationDeg - c.wrist.ulnarDeviationDeg) > 1e-3f;
    pose.orientationErrorDeg = rotationAngleDeg(pose.hand, target.handRotation);
    pose.reachErrorMm = glm::length(g.wrist - target.wristMm);
    pose.reachable = pose.reachErrorMm <= 0.5f;
    return pose;
}

}  // namespace signstim::hand
