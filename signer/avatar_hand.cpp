// The avatar's hands: palm, thumb and fingers as skinned tubes (avatar_mesh.hpp).
#include "signer/avatar_mesh.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace signstim::signer::avatar_mesh {

// The hand's geometry: a palm slab following the knuckle arc, a thumb and four fingers as
// continuous tubes (one skin across every knuckle; weights blend over each joint).
void buildHand(MeshBuilder& mesh, const hand::HandModel& model, hand::Side side,
               const glm::mat4& handWorld, const HandBones& bones) {
    const hand::HandPose pose = hand::forwardKinematics(model, hand::HandControls{}, side);
    const auto toWorld = [&](glm::vec3 mm) { return glm::vec3(handWorld * glm::vec4(mm, 1.0f)); };
    const glm::mat3 handRot = glm::mat3(handWorld) * (1.0f / kMmToM);  // rotation part (unit)
    const auto dirWorld = [&](glm::vec3 d) { return glm::normalize(handRot * d); };
    const auto& dims = model.dimensions;
    const auto bodyIndex = [](hand::Body b) { return static_cast<int>(b); };

    // Digit tubes.
    for (int digit = 0; digit < hand::kDigitCount; ++digit) {
        const int first = hand::firstBodyOf(static_cast<hand::Digit>(digit));
        std::array<glm::vec3, 4> joint{};  // base, two inner joints, tip (palm frame, mm)
        std::array<glm::quat, 3> rot{};
        for (int k = 0; k < 3; ++k) {
            joint[k] = pose.bodies[first + k].position;
            rot[k] = pose.bodies[first + k].rotation;
        }
        joint[3] = pose.tips[digit];
        std::array<float, 4> radius{};
        if (digit == 0) {
            radius = {12.0f, 10.5f, 9.5f, 8.0f};
        } else {
            const int f = digit - 1;
            const float pip = dims.pipWidthMm[f] * 0.5f, dip = dims.dipWidthMm[f] * 0.5f;
            radius = {pip * 1.08f, pip, dip, dip * 0.9f};
        }
        std::array<float, 4> at{};  // arc length of each joint
        for (int k = 1; k < 4; ++k) at[k] = at[k - 1] + glm::length(joint[k] - joint[k - 1]);
        const std::array<float, 3> blendHalf{digit == 0 ? 12.0f : 7.0f, radius[1] * 0.9f,
                                             radius[2] * 0.9f};
        const float startS = digit == 0 ? -6.0f : -10.0f;
        const float tipR = radius[3];
        std::vector<float> samples;
        for (float s = startS; s < at[3] - tipR; s += 2.0f) samples.push_back(s);
        samples.push_back(at[3] - tipR);
        std::vector<Ring> rings;
        const auto ringAt = [&](float s, float shrink, float extra) {
            int seg = 0;
            while (seg < 2 && s > at[seg + 1]) ++seg;
            const glm::vec3 axis = rot[seg] * glm::vec3(0, 0, 1);
            const glm::vec3 centerMm = joint[seg] + axis * (s - at[seg]) + axis * extra;
            float r;
            if (s <= 0.0f) r = radius[0];
            else {
                const float t = std::clamp((s - at[seg]) / (at[seg + 1] - at[seg]), 0.0f, 1.0f);
                r = radius[seg] + (radius[seg + 1] - radius[seg]) * t;
            }
            r *= shrink;
            Ring ring;
            ring.center = toWorld(centerMm);
            ring.u = dirWorld(rot[seg] * glm::vec3(1, 0, 0));
            ring.v = dirWorld(rot[seg] * glm::vec3(0, 1, 0));
            ring.ru = r * 0.88f * kMmToM;  // a little flatter palmar–dorsal
            ring.rv = r * kMmToM;
            ring.palmTone = true;
            // Weights: palm -> bone 0 -> bone 1 -> bone 2, each blended across its joint.
            Weights w(bones.hand);
            for (int k = 0; k < 3; ++k) {
                const float t = smoothstep(at[k] - blendHalf[k], at[k] + blendHalf[k], s);
                w = Weights::blend(w, Weights(bones.body[first + k]), t);
            }
            ring.weights = w;
            return ring;
        };
        if (digit == 0) {
            // Round the thumb's base: with the thumb spread away from the palm (G, L, Y) its
            // start shows beside the thenar, and a flat end would read as a cut.
            for (int k = 4; k >= 1; --k) {
                const float a = 0.5f * kPi * static_cast<float>(k) / 5.0f;
                rings.push_back(ringAt(startS, std::cos(a), -0.7f * radius[0] * std::sin(a)));
            }
        }
        for (float s : samples) rings.push_back(ringAt(s, 1.0f, 0.0f));
        // Round fingertip.
        for (int k = 1; k <= 4; ++k) {
            const float a = 0.5f * kPi * static_cast<float>(k) / 5.0f;
            rings.push_back(ringAt(at[3] - tipR, std::cos(a), tipR * std::sin(a)));
        }
        const float startPole = digit == 0 ? 0.7f * radius[0] * (1.0f - std::sin(0.4f * kPi)) + 0.3f : 1.0f;
        mesh.tube(kSkin, rings, 12, startPole * kMmToM, tipR * (1.0f - std::sin(0.4f * kPi)) * kMmToM + 0.3f * kMmToM);
        (void)bodyIndex;

        // Fingernail: a thin rounded plate on the dorsal side (-x) of the distal bone,
        // skinned rigidly to it. Built as a flat lens (unit ring: x across its thickness, y
        // across its width) bent onto the finger's elliptical section; its rim and its
        // proximal end (under the cuticle) sink just below the skin, its middle stands
        // ~0.4 mm proud. The distal skin is not rigid within blendHalf[2] of the DIP (weights
        // blend across the joint), so the nail starts beyond most of that blend.
        const float length = at[3] - at[2];
        const float capStart = length - tipR;  // the round fingertip cap begins here
        const float rCap = radius[2] + (radius[3] - radius[2]) * capStart / length;
        const auto sectionRadius = [&](float sd) {  // the skin's radius at sd along the bone
            if (sd <= capStart) return radius[2] + (radius[3] - radius[2]) * sd / length;
            const float q = std::min((sd - capStart) / tipR, 1.0f);
            return rCap * std::sqrt(1.0f - q * q);
        };
        const float nailEnd = length - 0.3f * tipR;
        const float nailStart = std::max(nailEnd - 0.62f * length, 0.8f * blendHalf[2]);
        const float halfWidth = 0.68f * radius[3];
        const float halfThick = 0.5f;
        const int nailRings = 10;
        std::vector<Ring> nail;
        for (int k = 0; k < nailRings; ++k) {
            // Denser toward both ends, where the outline rounds off.
            const float t = 0.02f + 0.96f * 0.5f * (1.0f - std::cos(kPi * static_cast<float>(k) / (nailRings - 1)));
            const float tProx = 0.35f, tDist = 0.2f;  // rounded cuticle, flatter free edge
            float outline = 1.0f;
            if (t < tProx) outline = std::sqrt(1.0f - std::pow((tProx - t) / tProx, 2.0f));
            if (t > 1.0f - tDist) outline = std::sqrt(1.0f - std::pow((t - (1.0f - tDist)) / tDist, 2.0f));
            const float sd = nailStart + t * (nailEnd - nailStart);
            const float w = halfWidth * outline;
            const float thick = halfThick * std::sqrt(outline);
            const float sink = 0.1f + 0.25f * (1.0f - smoothstep(0.0f, 0.3f, t));  // deeper at the cuticle
            Ring ring;
            ring.exponent = 2.5f;  // a flatter top than an ellipse: a plate
            ring.ru = ring.rv = 1.0f;  // unit ring, shaped by adjust
            ring.weights = Weights(bones.body[first + 2]);
            ring.adjust = [=, &toWorld, &sectionRadius, &joint, &rot](glm::vec3& p, Weights&, float, float) {
                // Unit ring: p.x across the thickness (+ outward), p.y across the width. y is
                // negated so the ring order keeps the tube's outward winding.
                const float y = -w * p.y;
                const float r = std::max(sectionRadius(sd), 1e-3f);
                const float yr = std::clamp(y / r, -1.0f, 1.0f);
                const float surface = 0.88f * r * std::sqrt(1.0f - yr * yr);  // dorsal skin
                const float x = -(surface - sink + thick * p.x);
                p = toWorld(joint[2] + rot[2] * glm::vec3(x, y, sd));
            };
            nail.push_back(ring);
        }
        render::Primitive& nails = mesh.primitive(kNail);
        const std::size_t nailBase = nails.vertices.size();
        mesh.tube(kNail, nail, 12, 0.0f, 0.0f);
        // Poles: the tube puts them at the unbent ring centres; move them to the centroids
        // of the end rings (the last two vertices: start, end).
        for (int end = 0; end < 2; ++end) {
            const std::size_t ringStart = nailBase + (end == 0 ? 0 : static_cast<std::size_t>(nailRings - 1) * 12);
            glm::vec3 c(0.0f);
            for (std::size_t j = 0; j < 12; ++j) c += nails.vertices[ringStart + j].position;
            nails.vertices[nails.vertices.size() - 2 + end].position = c / 12.0f;
        }
    }

    // Palm: slab from inside the sleeve (z = -30 mm) to just past the knuckle arc.
    std::array<glm::vec3, 4> mcp{};
    for (int f = 0; f < 4; ++f) mcp[f] = pose.bodies[hand::firstBodyOf(static_cast<hand::Digit>(f + 1))].position;
    const float ySign = side == hand::Side::Right ? 1.0f : -1.0f;  // +y toward the thumb (right)
    const auto knuckleZ = [&](float y) {  // z of the knuckle arc at palm-frame y (mirrored for left)
        const float ty = y * ySign;
        std::array<float, 4> ys{}, zs{};
        for (int f = 0; f < 4; ++f) { ys[f] = mcp[f].y * ySign; zs[f] = mcp[f].z; }
        if (ty >= ys[0]) return zs[0];
        if (ty <= ys[3]) return zs[3];
        for (int f = 0; f < 3; ++f)
            if (ty <= ys[f] && ty >= ys[f + 1]) {
                const float t = (ty - ys[f + 1]) / (ys[f] - ys[f + 1]);
                return zs[f + 1] + (zs[f] - zs[f + 1]) * t;
            }
        return zs[1];
    };
    const float thumbSideEdge = mcp[0].y * ySign + dims.pipWidthMm[0] * 0.5f + 1.0f;
    const float littleSideEdge = mcp[3].y * ySign - dims.pipWidthMm[3] * 0.5f - 1.0f;
    const glm::vec3 cmc = pose.bodies[bodyIndex(hand::Body::ThumbMetacarpal)].position;
    const glm::vec3 thumbMcp = pose.bodies[bodyIndex(hand::Body::ThumbProximal)].position;
    const float z0 = dims.palmWristZMm;  // the slab of HandDimensions (also the palm contact check)
    const int palmRings = 16;
    std::vector<Ring> rings;
    for (int i = 0; i <= palmRings; ++i) {
        const float s = static_cast<float>(i) / static_cast<float>(palmRings);
        // Width grows from the wrist to the knuckles; the thumb side bulges at the thenar.
        const float zNominal = z0 + s * (knuckleZ(0.0f) + 2.0f - z0);
        const float hiEdge = std::min(thumbSideEdge, 24.0f + 0.25f * std::max(zNominal, 0.0f)) +
                             6.0f * smoothstep(-5.0f, 20.0f, zNominal) * (1.0f - smoothstep(45.0f, 70.0f, zNominal));
        const float loEdge = std::max(littleSideEdge, -30.0f - 0.25f * std::max(zNominal, 0.0f));
        const float halfThick =
            dims.palmHalfThicknessWristMm + (dims.palmHalfThicknessKnucklesMm - dims.palmHalfThicknessWristMm) * s;
        Ring ring;
        ring.center = glm::vec3(0.0f);
        ring.exponent = 3.0f;
        // Built in palm-frame millimetres by `adjust`; u/v/ru/rv give the unit superellipse.
        ring.u = glm::vec3(1, 0, 0);
        ring.v = glm::vec3(0, 1, 0);
        ring.ru = 1.0f;
        ring.rv = 1.0f;
        ring.palmTone = true;
        ring.adjust = [=, &toWorld, &knuckleZ, &bones](glm::vec3& p, Weights& w, float, float) {
            const float xUnit = p.x, yUnit = p.y;
            // yUnit runs toward +y in both hands, so the mirrored left palm keeps its winding.
            const float yTrue = 0.5f * (hiEdge + loEdge) + 0.5f * (hiEdge - loEdge) * yUnit * ySign;
            const float y = yTrue * ySign;
            const float zEnd = knuckleZ(y) + 2.0f;
            const float z = z0 + s * (zEnd - z0);
            const float x = dims.palmCentreXMm + halfThick * xUnit;  // palmar side a little fleshier
            const glm::vec3 mm{x, y, z};
            // Weights: forearm at the wrist, hand, the proximal phalanges near the knuckles,
            // the thumb metacarpal over the thenar eminence.
            Weights weights = Weights::blend(Weights(bones.forearmTwistWrist), Weights(bones.hand),
                                             smoothstep(-18.0f, 14.0f, z));
            const float nearKnuckles = 0.4f * smoothstep(zEnd - 22.0f, zEnd + 2.0f, z);
            if (nearKnuckles > 0.0f) {
                const float ty = yTrue;
                int f = 0;
                while (f < 3 && ty < mcp[f + 1].y * ySign) ++f;
                // f: the finger whose MCP is at or below ty (toward the little finger).
                const int lower = std::min(f + 1, 3), upper = f;
                const float yu = mcp[upper].y * ySign, yl = mcp[lower].y * ySign;
                const float t = lower == upper ? 0.0f : std::clamp((yu - ty) / (yu - yl), 0.0f, 1.0f);
                Weights fingers = Weights::blend(
                    Weights(bones.body[hand::firstBodyOf(static_cast<hand::Digit>(upper + 1))]),
                    Weights(bones.body[hand::firstBodyOf(static_cast<hand::Digit>(lower + 1))]), t);
                weights = Weights::blend(weights, fingers, nearKnuckles);
            }
            // Thenar: distance to the thumb metacarpal segment.
            const glm::vec3 seg = thumbMcp - cmc;
            const float h = std::clamp(glm::dot(mm - cmc, seg) / glm::dot(seg, seg), 0.0f, 1.0f);
            const float dist = glm::length(mm - (cmc + h * seg));
            const float thenar = 0.4f * (1.0f - smoothstep(8.0f, 45.0f, dist));
            weights = Weights::blend(weights, Weights(bones.body[bodyIndex(hand::Body::ThumbMetacarpal)]), thenar);
            p = toWorld(mm);
            w = weights;
        };
        rings.push_back(ring);
    }
    // The fan poles of a unit ring sit at the ring centre in palm units; place the slab's
    // poles by hand below (tube() puts them at centre ± axis·offset of the unadjusted ring).
    MeshBuilder palm;
    palm.tube(kSkin, rings, 32, 0.0f, 0.0f);
    std::vector<render::Primitive> parts = palm.finish();
    render::Primitive& slab = parts.front();
    // Poles: the last two vertices (start, end); move them to the end-ring centroids.
    const std::size_t n = 32;
    for (int end = 0; end < 2; ++end) {
        const std::size_t ringStart = end == 0 ? 0 : static_cast<std::size_t>(palmRings) * n;
        const std::size_t poleIndex = end == 0 ? slab.vertices.size() - 2 : slab.vertices.size() - 1;
        glm::vec3 c(0.0f);
        Weights average;
        for (std::size_t j = 0; j < n; ++j) {
            const render::Vertex& v = slab.vertices[ringStart + j];
            c += v.position;
            for (int k = 0; k < 4; ++k) average.add(static_cast<int>(v.joints[k]), v.weights[k]);
        }
        c /= static_cast<float>(n);
        slab.vertices[poleIndex].position = c;
        average.toVertex(slab.vertices[poleIndex]);
    }
    render::Primitive& skin = mesh.primitive(kSkin);
    const auto base = static_cast<std::uint32_t>(skin.vertices.size());
    skin.vertices.insert(skin.vertices.end(), slab.vertices.begin(), slab.vertices.end());
    for (std::uint32_t idx : slab.indices) skin.indices.push_back(base + idx);
}

}  // namespace signstim::signer::avatar_mesh
