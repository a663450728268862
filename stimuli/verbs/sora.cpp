#include "stimuli/verbs/sora.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace signstim::stimuli {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

glm::dquat normalizedPositiveW(glm::dquat q) {
    q = glm::normalize(q);
    if (q.w < 0.0) q = -q;
    return q;
}

// Row r, column c of a column-major glm matrix.
double at(const glm::dmat3& m, int row, int column) { return m[column][row]; }

}  // namespace

glm::dquat soraToQuaternion(const Sora& phi) {
    const double angle = glm::length(phi);
    if (angle < 1e-12) {
        // First-order expansion keeps tiny rotations exact to rounding.
        return glm::normalize(glm::dquat(1.0, 0.5 * phi.x, 0.5 * phi.y, 0.5 * phi.z));
    }
    const double s = std::sin(0.5 * angle) / angle;
    return glm::dquat(std::cos(0.5 * angle), s * phi.x, s * phi.y, s * phi.z);
}

Sora quaternionToSora(const glm::dquat& quaternion) {
    const glm::dquat q = normalizedPositiveW(quaternion);
    const glm::dvec3 v(q.x, q.y, q.z);
    const double vectorLength = glm::length(v);
    if (vectorLength < 1e-15) return 2.0 * v;
    // SPEC §3.6: θ = 2·atan2(|q_v|, q_w) is accurate near 0 and near π alike.
    const double angle = 2.0 * std::atan2(vectorLength, q.w);
    return (angle / vectorLength) * v;
}

glm::dmat3 soraToMatrix(const Sora& phi) {
    const double angle = glm::length(phi);
    glm::dmat3 result(1.0);
    if (angle < 1e-15) return result;
    const glm::dvec3 k = phi / angle;
    // Rodrigues: R = I + sin θ K + (1 − cos θ) K², K the cross-product matrix of k.
    glm::dmat3 cross(0.0);  // column-major: cross[column][row]
    cross[1][0] = -k.z; cross[2][0] = k.y;
    cross[0][1] = k.z;  cross[2][1] = -k.x;
    cross[0][2] = -k.y; cross[1][2] = k.x;
    result += std::sin(angle) * cross + (1.0 - std::cos(angle)) * (cross * cross);
    return result;
}

glm::dquat matrixToQuaternion(const glm::dmat3& m) {
    const double trace = at(m, 0, 0) + at(m, 1, 1) + at(m, 2, 2);
    glm::dquat q;
    // Shepperd: divide by the largest of 4w², 4x², 4y², 4z² so no cancellation occurs.
    if (trace >= at(m, 0, 0) && trace >= at(m, 1, 1) && trace >= at(m, 2, 2)) {
        const double r = std::sqrt(1.0 + trace);
        const double s = 0.5 / r;
        q = glm::dquat(0.5 * r, (at(m, 2, 1) - at(m, 1, 2)) * s, (at(m, 0, 2) - at(m, 2, 0)) * s,
                       (at(m, 1, 0) - at(m, 0, 1)) * s);
    } else if (at(m, 0, 0) >= at(m, 1, 1) && at(m, 0, 0) >= at(m, 2, 2)) {
        const double r = std::sqrt(std::max(0.0, 1.0 + at(m, 0, 0) - at(m, 1, 1) - at(m, 2, 2)));
        const double s = 0.5 / r;
        q = glm::dquat((at(m, 2, 1) - at(m, 1, 2)) * s, 0.5 * r, (at(m, 0, 1) + at(m, 1, 0)) * s,
                       (at(m, 0, 2) + at(m, 2, 0)) * s);
    } else if (at(m, 1, 1) >= at(m, 2, 2)) {
        const double r = std::sqrt(std::max(0.0, 1.0 + at(m, 1, 1) - at(m, 0, 0) - at(m, 2, 2)));
        const double s = 0.5 / r;
        q = glm::dquat((at(m, 0, 2) - at(m, 2, 0)) * s, (at(m, 0, 1) + at(m, 1, 0)) * s, 0.5 * r,
                       (at(m, 1, 2) + at(m, 2, 1)) * s);
    } else {
        const double r = std::sqrt(std::max(0.0, 1.0 + at(m, 2, 2) - at(m, 0, 0) - at(m, 1, 1)));
        const double s = 0.5 / r;
        q = glm::dquat((at(m, 1, 0) - at(m, 0, 1)) * s, (at(m, 0, 2) + at(m, 2, 0)) * s,
                       (at(m, 1, 2) + at(m, 2, 1)) * s, 0.5 * r);
    }
    return normalizedPositiveW(q);
}

Sora matrixToSora(const glm::dmat3& rotation) { return quaternionToSora(matrixToQuaternion(rotation)); }

AxisAngle soraToAxisAngle(const Sora& phi) {
    const double angle = glm::length(phi);
    if (angle < 1e-15) return AxisAngle{};
    return AxisAngle{phi / angle, angle};
}

Sora axisAngleToSora(const AxisAngle& axisAngle) {
    const double length = glm::length(axisAngle.axis);
    if (length < 1e-15) return Sora(0.0);
    return (axisAngle.angleRadians / length) * axisAngle.axis;
}

glm::dquat rollPitchYawDegreesToQuaternion(double rollDeg, double pitchDeg, double yawDeg) {
    const auto about = [](double angleRad, const glm::dvec3& axis) {
        return glm::dquat(std::cos(0.5 * angleRad), std::sin(0.5 * angleRad) * axis.x,
                          std::sin(0.5 * angleRad) * axis.y, std::sin(0.5 * angleRad) * axis.z);
    };
    const glm::dquat roll = about(rollDeg * kDegree, {1, 0, 0});
    const glm::dquat pitch = about(pitchDeg * kDegree, {0, 1, 0});
    const glm::dquat yaw = about(yawDeg * kDegree, {0, 0, 1});
    return normalizedPositiveW(yaw * pitch * roll);
}

glm::dvec3 quaternionToRollPitchYawDegrees(const glm::dquat& q) {
    const glm::dmat3 m = glm::mat3_cast(glm::normalize(q));
    // R = Rz(ψ)Ry(θ)Rx(φ): R20 = −sin θ, R21 = cos θ sin φ, R22 = cos θ cos φ,
    // R10 = sin ψ cos θ, R00 = cos ψ cos θ.
    const double sinPitch = std::clamp(-at(m, 2, 0), -1.0, 1.0);
    const double pitch = std::asin(sinPitch);
    double roll = 0.0;
    double yaw = 0.0;
    if (std::abs(sinPitch) < 1.0 - 1e-12) {
        roll = std::atan2(at(m, 2, 1), at(m, 2, 2));
        yaw = std::atan2(at(m, 1, 0), at(m, 0, 0));
    } else {
        // Gimbal lock: only yaw ∓ roll is defined; put it all in yaw.
        yaw = std::atan2(-at(m, 0, 1), at(m, 1, 1));
    }
    return glm::dvec3(roll, pitch, yaw) / kDegree;
}

glm::dquat orientationFromFingersPalm(const glm::dvec3& fingers, const glm::dvec3& palm) {
    const double fingersLength = glm::length(fingers);
    if (!(fingersLength > 1e-9)) throw std::invalid_argument("the fingers direction is zero");
    const glm::dvec3 z = fingers / fingersLength;
    const glm::dvec3 palmOrthogonal = palm - glm::dot(palm, z) * z;
    const double palmLength = glm::length(palmOrthogonal);
    if (!(palmLength > 1e-6 * std::max(1.0, glm::length(palm)))) {
        throw std::invalid_argument("the palm direction is zero or parallel to the fingers");
    }
    const glm::dvec3 x = palmOrthogonal / palmLength;
    const glm::dvec3 y = glm::cross(z, x);
    return matrixToQuaternion(glm::dmat3(x, y, z));
}

glm::dvec3 fingersDirection(const glm::dquat& orientation) { return orientation * glm::dvec3(0, 0, 1); }
glm::dvec3 palmDirection(const glm::dquat& orientation) { return orientation * glm::dvec3(1, 0, 0); }

glm::dquat slerpShortest(const glm::dquat& from, const glm::dquat& to, double t) {
    glm::dquat target = to;
    double cosine = glm::dot(from, to);
    if (cosine < 0.0) {
        target = -to;
        cosine = -cosine;
    }
    if (cosine > 1.0 - 1e-12) return glm::normalize(from * (1.0 - t) + target * t);
    const double angle = std::acos(std::min(1.0, cosine));
    const double sinAngle = std::sin(angle);
    return glm::normalize(from * (std::sin((1.0 - t) * angle) / sinAngle) +
                          target * (std::sin(t * angle) / sinAngle));
}

double rotationAngleBetween(const glm::dquat& a, const glm::dquat& b) {
    const double cosine = std::abs(glm::dot(glm::normalize(a), glm::normalize(b)));
    return 2.0 * std::acos(std::min(1.0, cosine));
}

glm::dquat meanRotation(const std::vector<glm::dquat>& rotations) {
    if (rotations.empty()) throw std::invalid_argument("meanRotation of no rotations");
    Eigen::Matrix4d scatter = Eigen::Matrix4d::Zero();
    for (const glm::dquat& r : rotations) {
        const glm::dquat q = glm::normalize(r);
        const Eigen::Vector4d v(q.w, q.x, q.y, q.z);
        scatter += v * v.transpose();
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> solver(scatter);
    const Eigen::Vector4d v = solver.eigenvectors().col(3);  // largest eigenvalue
    return normalizedPositiveW(glm::dquat(v(0), v(1), v(2), v(3)));
}

}  // namespace signstim::stimuli
