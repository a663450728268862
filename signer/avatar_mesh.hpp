#pragma once
// The avatar's mesh building, shared by avatar_builder.cpp (body, head, face) and
// avatar_hand.cpp (the hands): skin weights, tube rings, the mesh builder and the materials.
#include "signer/avatar_builder.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace signstim::signer::avatar_mesh {

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kMmToM = 0.001f;

inline float smoothstep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// ---- skin weights ---------------------------------------------------------------------
// Up to four influences, normalised to sum 1, heaviest first (ties by joint index, so the
// output is deterministic).
struct Weights {
    std::vector<std::pair<int, float>> influences;
    Weights() = default;
    Weights(int joint) { influences.push_back({joint, 1.0f}); }  // NOLINT: rigid
    Weights& add(int joint, float w) {
        if (w <= 0.0f) return *this;
        for (auto& [j, v] : influences)
            if (j == joint) { v += w; return *this; }
        influences.push_back({joint, w});
        return *this;
    }
    static Weights blend(const Weights& a, const Weights& b, float t) {
        Weights r;
        for (auto [j, w] : a.influences) r.add(j, w * (1.0f - t));
        for (auto [j, w] : b.influences) r.add(j, w * t);
        return r;
    }
    void toVertex(render::Vertex& v) const {
        auto sorted = influences;
        std::sort(sorted.begin(), sorted.end(), [](const auto& x, const auto& y) {
            return x.second != y.second ? x.second > y.second : x.first < y.first;
        });
        if (sorted.size() > 4) sorted.resize(4);
        float sum = 0.0f;
        for (auto [j, w] : sorted) sum += w;
        v.joints = glm::uvec4(0u);
        v.weights = glm::vec4(0.0f);
        for (std::size_t i = 0; i < sorted.size(); ++i) {
            v.joints[static_cast<int>(i)] = static_cast<unsigned>(sorted[i].first);
            v.weights[static_cast<int>(i)] = sorted[i].second / sum;
        }
    }
};

// ---- mesh building ----------------------------------------------------------------------
// A cross-section of a tube: centre, two perpendicular half-axes (u × v points along the
// tube) and a superellipse exponent (2 = ellipse, larger = boxier).
struct Ring {
    glm::vec3 center{0.0f};
    glm::vec3 u{1, 0, 0}, v{0, 1, 0};
    float ru = 0.01f, rv = 0.01f;
    Weights weights;
    float exponent = 2.0f;
    // Hand skin: the texture coordinate carries the palmar–dorsal tone (see skinToneU).
    bool palmTone = false;
    // Optional per-point override (palm: the distal edge follows the knuckle arc).
    std::function<void(glm::vec3& p, Weights& w, float cosA, float sinA)> adjust;
};

// The skin material's base colour is a 2×1 texture: texel 0 the back of the hand (and the
// face), texel 1 the palm, slightly lighter and pinker as on real hands. Hand vertices pick
// their tone with u (linear filtering blends the two over the sides of the fingers and the
// edges of the palm); every other skin vertex keeps u = 0, the back tone.
inline constexpr float kBackU = 0.25f, kPalmU = 0.75f;  // texel centres
// c: cosine of the vertex's angle from the palmar direction (+1 palmar, -1 dorsal).
inline float skinToneU(float c) { return kBackU + (kPalmU - kBackU) * smoothstep(-0.25f, 0.35f, c); }

inline float superPow(float c, float exponent) {
    return std::copysign(std::pow(std::fabs(c), 2.0f / exponent), c);
}

class MeshBuilder {
public:
    render::Primitive& primitive(int material) {
        auto it = primitives_.find(material);
        if (it == primitives_.end()) {
            render::Primitive p;
            p.material = material;
            p.skinned = true;
            it = primitives_.emplace(material, std::move(p)).first;
        }
        return it->second;
    }

    // A closed tube through `rings`, closed at both ends by a fan to a pole a little beyond
    // the end rings (round caps come from rings that shrink toward the ends).
    void tube(int material, const std::vector<Ring>& rings, int segments, float startPoleOffset,
              float endPoleOffset) {
        render::Primitive& p = primitive(material);
        const auto base = static_cast<std::uint32_t>(p.vertices.size());
        for (const Ring& ring : rings) {
            for (int j = 0; j < segments; ++j) {
                const float a = 2.0f * kPi * static_cast<float>(j) / static_cast<float>(segments);
                const float c = std::cos(a), s = std::sin(a);
                glm::vec3 pos = ring.center + ring.ru * superPow(c, ring.exponent) * ring.u +
                                ring.rv * superPow(s, ring.exponent) * ring.v;
                Weights w = ring.weights;
                if (ring.adjust) ring.adjust(pos, w, c, s);
                render::Vertex v;
                v.position = pos;
                if (ring.palmTone) v.uv = {skinToneU(c), 0.5f};
                w.toVertex(v);
                p.vertices.push_back(v);
            }
        }
        const auto n = static_cast<std::uint32_t>(segments);
        for (std::uint32_t i = 0; i + 1 < rings.size(); ++i)
            for (std::uint32_t j = 0; j < n; ++j) {
                const std::uint32_t a = base + i * n + j, b = base + i * n + (j + 1) % n;
                const std::uint32_t c = a + n, d = b + n;
                p.indices.insert(p.indices.end(), {a, b, c, b, d, c});
            }
        // Poles.
        const auto addPole = [&](const Ring& ring, float offset, bool atEnd) {
            const glm::vec3 axis = glm::normalize(glm::cross(ring.u, ring.v));
            render::Vertex v;
            v.position = ring.center + axis * offset;
            if (ring.palmTone) v.uv = {skinToneU(0.0f), 0.5f};
            Weights w = ring.weights;
            w.toVertex(v);
            const auto pole = static_cast<std::uint32_t>(p.vertices.size());
            p.vertices.push_back(v);
            const std::uint32_t first =
                base + (atEnd ? static_cast<std::uint32_t>(rings.size() - 1) * n : 0u);
            for (std::uint32_t j = 0; j < n; ++j) {
                const std::uint32_t a = first + j, b = first + (j + 1) % n;
                if (atEnd) p.indices.insert(p.indices.end(), {a, b, pole});
                else p.indices.insert(p.indices.end(), {a, pole, b});
            }
        };
        addPole(rings.front(), -startPoleOffset, false);
        addPole(rings.back(), endPoleOffset, true);
    }

    // Ellipsoid with half-axes `radii` along the columns of `axes`; `taper` may reshape it.
    void ellipsoid(int material, glm::vec3 center, glm::vec3 radii, const glm::mat3& axes,
                   const Weights& weights, int segments, int stacks,
                   const std::function<void(glm::vec3& local)>& taper = {}) {
        std::vector<Ring> rings;
        for (int i = 1; i < stacks; ++i) {
            const float lat = -0.5f * kPi + kPi * static_cast<float>(i) / static_cast<float>(stacks);
            Ring r;
            r.center = center + axes[2] * (radii.z * std::sin(lat));
            r.u = axes[0];
            r.v = axes[1];
            r.ru = radii.x * std::cos(lat);
            r.rv = radii.y * std::cos(lat);
            r.weights = weights;
            if (taper) {
                r.adjust = [center, axes, taper](glm::vec3& p, Weights&, float, float) {
                    glm::vec3 local = glm::transpose(axes) * (p - center);
                    taper(local);
                    p = center + axes * local;
                };
            }
            rings.push_back(r);
        }
        const float poleLat = -0.5f * kPi + kPi / static_cast<float>(stacks);
        const float gap = radii.z * (1.0f - std::cos(0.5f * kPi + poleLat));
        tube(material, rings, segments, gap, gap);
    }

    // A patch from rows of points (each row the same length), every triangle turned to face
    // away from `inside` (a shell around a point: the eyelids).
    void grid(int material, const std::vector<std::vector<glm::vec3>>& rows, const Weights& weights,
              glm::vec3 inside) {
        render::Primitive& p = primitive(material);
        const auto base = static_cast<std::uint32_t>(p.vertices.size());
        const auto n = static_cast<std::uint32_t>(rows.front().size());
        for (const auto& row : rows)
            for (const glm::vec3& pos : row) {
                render::Vertex v;
                v.position = pos;
                weights.toVertex(v);
                p.vertices.push_back(v);
            }
        const auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
            const glm::vec3 pa = p.vertices[a].position, pb = p.vertices[b].position, pc = p.vertices[c].position;
            if (glm::dot(glm::cross(pb - pa, pc - pa), (pa + pb + pc) / 3.0f - inside) < 0.0f) std::swap(b, c);
            p.indices.insert(p.indices.end(), {a, b, c});
        };
        for (std::uint32_t i = 0; i + 1 < rows.size(); ++i)
            for (std::uint32_t j = 0; j + 1 < n; ++j) {
                const std::uint32_t a = base + i * n + j, b = a + 1, c = a + n, d = c + 1;
                add(a, b, c);
                add(b, d, c);
            }
    }

    std::vector<render::Primitive> finish() {
        std::vector<render::Primitive> out;
        for (auto& [material, p] : primitives_) {
            computeNormals(p);
            out.push_back(std::move(p));
        }
        return out;
    }

    // Area-weighted vertex normals of the triangles (also of a morph target's shape).
    static void computeNormals(render::Primitive& p) {
        std::vector<glm::vec3> normals(p.vertices.size(), glm::vec3(0.0f));
        for (std::size_t t = 0; t + 2 < p.indices.size(); t += 3) {
            const glm::vec3 a = p.vertices[p.indices[t]].position;
            const glm::vec3 b = p.vertices[p.indices[t + 1]].position;
            const glm::vec3 c = p.vertices[p.indices[t + 2]].position;
            const glm::vec3 n = glm::cross(b - a, c - a);  // area-weighted
            for (int k = 0; k < 3; ++k) normals[p.indices[t + k]] += n;
        }
        for (std::size_t i = 0; i < normals.size(); ++i) {
            const float len = glm::length(normals[i]);
            p.vertices[i].normal = len > 1e-12f ? normals[i] / len : glm::vec3(0, 0, 1);
        }
    }
private:
    std::map<int, render::Primitive> primitives_;
};

// The avatar's materials, in the order of avatarMaterials() (avatar_builder.cpp).
enum MaterialId { kSkin = 0, kTop, kEyeWhite, kIris, kHair, kLips, kNail, kPupil, kMouth };

// The default signer's face (signer/avatar_face_mesh.cpp): the head's skin, brows, eyelids and
// lashes, nose, lips, the mouth's dark opening and the tongue, as a mesh of its own skinned to
// the head bone with the morph targets of faceTargetNames() (signer/avatar_face.hpp). The
// eyeballs (turned by the eye bones) are not part of it. Positions in the rest pose, metres:
// `headWorld` the head bone, `eyeLocal` the left eye bone from it (the right mirrored).
render::Mesh buildFaceMesh(const glm::vec3& headWorld, const glm::vec3& eyeLocal, int headBone);
// The face's geometry constants shared with avatar_builder.cpp.
inline constexpr float kEyeballRadiusM = 0.012f;

struct HandBones {
    int hand = -1;
    std::array<int, hand::kBodyCount> body{};  // node index per hand::Body (body[0] = hand)
    int forearmTwistWrist = -1;
};

// The hand's geometry: a palm slab following the knuckle arc, a thumb and four fingers as
// continuous tubes (one skin across every knuckle; weights blend over each joint).
void buildHand(MeshBuilder& mesh, const hand::HandModel& model, hand::Side side,
               const glm::mat4& handWorld, const HandBones& bones);

}  // namespace signstim::signer::avatar_mesh
