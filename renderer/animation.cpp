// glTF 2.0 animation sampling (spec §3.11 and Appendix C: interpolation), morph-target
// weights included.
#include "renderer/scene.hpp"

#include <algorithm>
#include <cmath>

namespace signstim::render {
namespace {

glm::quat toQuat(const glm::vec4& v) { return glm::quat(v.w, v.x, v.y, v.z); }

glm::quat slerpShortest(glm::quat a, glm::quat b, float u) {
    float cosine = glm::dot(a, b);
    if (cosine < 0.0f) {  // q and -q are the same rotation: take the short way round
        b = -b;
        cosine = -cosine;
    }
    if (cosine > 0.9995f) return glm::normalize(a * (1.0f - u) + b * u);
    const float angle = std::acos(std::min(cosine, 1.0f));
    const float s = std::sin(angle);
    return glm::normalize(a * (std::sin((1.0f - u) * angle) / s) + b * (std::sin(u * angle) / s));
}

// Sampled value as vec4 (quaternion xyzw for rotations).
glm::vec4 sample(const AnimationSampler& sampler, float t, bool rotation) {
    const std::vector<float>& times = sampler.times;
    const bool cubic = sampler.interpolation == Interpolation::CubicSpline;
    const std::size_t stride = cubic ? 3 : 1, valueOffset = cubic ? 1 : 0;
    auto value = [&](std::size_t key) { return sampler.values[key * stride + valueOffset]; };
    if (times.size() == 1 || t <= times.front()) return value(0);
    if (t >= times.back()) return value(times.size() - 1);
    const std::size_t k = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
    const float dt = times[k + 1] - times[k];
    const float u = dt > 0.0f ? (t - times[k]) / dt : 1.0f;
    switch (sampler.interpolation) {
        case Interpolation::Step:
            return value(k);
        case Interpolation::Linear:
            if (rotation) {
                const glm::quat q = slerpShortest(toQuat(value(k)), toQuat(value(k + 1)), u);
                return glm::vec4(q.x, q.y, q.z, q.w);
            }
            return glm::mix(value(k), value(k + 1), u);
        case Interpolation::CubicSpline: {
            // Hermite: p = h00 v_k + h10 dt b_k + h01 v_k+1 + h11 dt a_k+1 (b: out-, a: in-tangent).
            const float u2 = u * u, u3 = u2 * u;
            const glm::vec4 outTangent = sampler.values[k * 3 + 2];
            const glm::vec4 inTangent = sampler.values[(k + 1) * 3];
            glm::vec4 p = (2 * u3 - 3 * u2 + 1) * value(k) + (u3 - 2 * u2 + u) * dt * outTangent +
                          (-2 * u3 + 3 * u2) * value(k + 1) + (u3 - u2) * dt * inTangent;
            if (rotation) {
                const float length = glm::length(p);
                p = length > 0.0f ? p / length : value(k);
            }
            return p;
        }
    }
    return value(k);
}

// Morph-target weights at `t` (glTF 2.0 Appendix C, component by component): `count`
// weights per key. LINEAR is a lerp, STEP holds, CUBICSPLINE a Hermite spline.
void sampleWeights(const AnimationSampler& sampler, float t, std::vector<float>& out) {
    const std::size_t count = sampler.weightCount;
    const std::vector<float>& times = sampler.times;
    const bool cubic = sampler.interpolation == Interpolation::CubicSpline;
    // Element e of key k's in-tangent (part 0), value (1) or out-tangent (2).
    auto at = [&](std::size_t key, std::size_t part, std::size_t e) {
        return sampler.weights[(cubic ? key * 3 + part : key) * count + e];
    };
    const std::size_t valuePart = cubic ? 1 : 0;
    out.assign(count, 0.0f);
    if (count == 0 || times.empty() || sampler.weights.size() < times.size() * count * (cubic ? 3 : 1)) return;
    std::size_t k = 0;
    float u = 0.0f, dt = 0.0f;
    bool between = false;
    if (times.size() == 1 || t <= times.front()) {
        k = 0;
    } else if (t >= times.back()) {
        k = times.size() - 1;
    } else {
        k = static_cast<std::size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) - 1;
        dt = times[k + 1] - times[k];
        u = dt > 0.0f ? (t - times[k]) / dt : 1.0f;
        between = sampler.interpolation != Interpolation::Step;
    }
    for (std::size_t e = 0; e < count; ++e) {
        if (!between) {
            out[e] = at(k, valuePart, e);
        } else if (!cubic) {
            out[e] = at(k, 0, e) + (at(k + 1, 0, e) - at(k, 0, e)) * u;
        } else {
            const float u2 = u * u, u3 = u2 * u;
            out[e] = (2 * u3 - 3 * u2 + 1) * at(k, 1, e) + (u3 - 2 * u2 + u) * dt * at(k, 2, e) +
                     (-2 * u3 + 3 * u2) * at(k + 1, 1, e) + (u3 - u2) * dt * at(k + 1, 0, e);
        }
    }
}

}  // namespace

void applyAnimation(const Scene& scene, int animation, float timeSeconds, Pose& pose) {
    if (animation < 0 || static_cast<std::size_t>(animation) >= scene.animations.size()) return;
    // A pose shorter than the scene (e.g. empty) is completed with rest values.
    for (std::size_t i = pose.local.size(); i < scene.nodes.size(); ++i) pose.local.push_back(scene.nodes[i].rest);
    for (std::size_t i = pose.useRestMatrix.size(); i < scene.nodes.size(); ++i)
        pose.useRestMatrix.push_back(i < pose.local.size() && scene.nodes[i].restMatrix.has_value());
    const Animation& a = scene.animations[static_cast<std::size_t>(animation)];
    const float t = std::clamp(std::isfinite(timeSeconds) ? timeSeconds : 0.0f, 0.0f, a.durationSeconds);
    for (const AnimationChannel& channel : a.channels) {
        if (channel.node < 0 || static_cast<std::size_t>(channel.node) >= scene.nodes.size()) continue;
        if (channel.sampler < 0 || static_cast<std::size_t>(channel.sampler) >= a.samplers.size()) continue;
        const AnimationSampler& sampler = a.samplers[static_cast<std::size_t>(channel.sampler)];
        if (sampler.times.empty()) continue;
        if (channel.path == AnimationPath::Weights) {
            if (pose.morphWeights.size() < scene.nodes.size()) pose.morphWeights.resize(scene.nodes.size());
            sampleWeights(sampler, t, pose.morphWeights[static_cast<std::size_t>(channel.node)]);
            continue;
        }
        const bool rotation = channel.path == AnimationPath::Rotation;
        const glm::vec4 v = sample(sampler, t, rotation);
        Trs& local = pose.local[static_cast<std::size_t>(channel.node)];
        switch (channel.path) {
            case AnimationPath::Translation: local.translation = glm::vec3(v); break;
            case AnimationPath::Scale: local.scale = glm::vec3(v); break;
            case AnimationPath::Rotation: local.rotation = glm::normalize(toQuat(v)); break;
            case AnimationPath::Weights: break;  // handled above
        }
        pose.useRestMatrix[static_cast<std::size_t>(channel.node)] = false;
    }
}

}  // namespace signstim::render
