#include "signer/avatar_builder.hpp"

#include "hand/arm_ik.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <utility>

namespace signstim::signer {
namespace {

constexpr float kPi = 3.14159265358979323846f;
constexpr float kMmToM = 0.001f;

float smoothstep(float edge0, float edge1, float x) {
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
constexpr float kBackU = 0.25f, kPalmU = 0.75f;  // texel centres
// c: cosine of the vertex's angle from the palmar direction (+1 palmar, -1 dorsal).
float skinToneU(float c) { return kBackU + (kPalmU - kBackU) * smoothstep(-0.25f, 0.35f, c); }

float superPow(float c, float exponent) {
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

    std::vector<render::Primitive> finish() {
        std::vector<render::Primitive> out;
        for (auto& [material, p] : primitives_) {
            computeNormals(p);
            out.push_back(std::move(p));
        }
        return out;
    }

private:
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
    std::map<int, render::Primitive> primitives_;
};

// ---- skeleton --------------------------------------------------------------------------
struct SkeletonBuilder {
    render::Scene& scene;
    int add(const std::string& name, int parent, glm::vec3 translation,
            glm::quat rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
        render::Node node;
        node.name = name;
        node.parent = parent;
        node.rest.translation = translation;
        node.rest.rotation = rotation;
        const int index = static_cast<int>(scene.nodes.size());
        scene.nodes.push_back(node);
        if (parent >= 0) scene.nodes[parent].children.push_back(index);
        else scene.roots.push_back(index);
        return index;
    }
};

std::string sideName(hand::Side side) { return side == hand::Side::Right ? "right" : "left"; }

// Materials (linear RGB). Sign-language video practice: a plain dark top, skin that contrasts
// with it, a plain background and even light (the renderer's defaults).
enum MaterialId { kSkin = 0, kTop, kEyeWhite, kIris, kHair, kLips, kNail };

std::vector<render::Material> avatarMaterials() {
    const auto make = [](const char* name, glm::vec3 color, float roughness) {
        render::Material m;
        m.name = name;
        m.baseColorFactor = glm::vec4(color, 1.0f);
        m.metallicFactor = 0.0f;
        m.roughnessFactor = roughness;
        return m;
    };
    render::Material skin = make("skin", {1.0f, 1.0f, 1.0f}, 0.65f);
    skin.baseColorTexture = 0;  // skinToneTexture(): back (0.56, 0.33, 0.22), palm lighter
    return {skin,
            make("top", {0.018f, 0.020f, 0.028f}, 0.85f),
            make("eyeWhite", {0.78f, 0.77f, 0.74f}, 0.35f),
            make("iris", {0.16f, 0.09f, 0.045f}, 0.3f),  // brown, lighter than the pupil
            make("hair", {0.022f, 0.015f, 0.011f}, 0.75f),
            make("lips", {0.36f, 0.12f, 0.10f}, 0.5f),
            // Paler and pinker than the skin, a little glossy: the back of a finger reads
            // as the back (from the front a curled finger's back otherwise looks like a palm).
            make("nail", {0.72f, 0.47f, 0.42f}, 0.45f)};
}

std::uint8_t srgbByte(float linear) {
    const float s = linear <= 0.0031308f ? 12.92f * linear : 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(std::clamp(s, 0.0f, 1.0f) * 255.0f));
}

// The skin tones (linear RGB; stored sRGB as glTF base-colour textures are).
void addSkinToneTexture(render::Scene& scene) {
    const glm::vec3 back{0.56f, 0.33f, 0.22f}, palm{0.66f, 0.38f, 0.29f};
    render::ImageData image;
    image.name = "skinTone";
    image.width = 2;
    image.height = 1;
    for (const glm::vec3& c : {back, palm})
        image.rgba.insert(image.rgba.end(), {srgbByte(c.r), srgbByte(c.g), srgbByte(c.b), 255});
    scene.images.push_back(std::move(image));
    render::Texture texture;
    texture.image = 0;
    texture.mipmaps = false;
    texture.wrapS = texture.wrapT = render::Wrap::ClampToEdge;
    scene.textures.push_back(texture);
}

struct HandBones {
    int hand = -1;
    std::array<int, hand::kBodyCount> body{};  // node index per hand::Body (body[0] = hand)
    int forearmTwistWrist = -1;
};

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

}  // namespace

const std::vector<std::string>& requiredAvatarBones() {
    static const std::vector<std::string> bones = [] {
        std::vector<std::string> b{"hips", "spine", "chest", "neck", "head"};
        for (hand::Side side : {hand::Side::Left, hand::Side::Right}) {
            const std::string s = sideName(side);
            for (const char* part : {"Shoulder", "UpperArm", "LowerArm"}) b.push_back(s + part);
            for (const auto& bone : hand::handBones(side)) b.emplace_back(bone.name);
        }
        return b;
    }();
    return bones;
}

render::Scene buildDefaultAvatar(const AvatarDimensions& d) {
    render::Scene scene;
    scene.sourceName = "signstim default signer";
    SkeletonBuilder sk{scene};
    const int hips = sk.add("hips", -1, d.hipsM);
    const int spine = sk.add("spine", hips, {0.0f, 0.12f, 0.0f});
    const int chest = sk.add("chest", spine, d.chestM - d.hipsM - glm::vec3(0.0f, 0.12f, 0.0f));
    const int neck = sk.add("neck", chest, {0.0f, 0.15f, -0.01f});
    const int head = sk.add("head", neck, {0.0f, 0.09f, 0.01f});
    const glm::vec3 headWorld = d.chestM + glm::vec3(0.0f, 0.24f, 0.0f);
    // The eyeballs stand 4 mm proud of the face (skin at z ≈ 0.098 here), so ~18 mm of each
    // shows: open eyes whose irises turn with the gaze. Set 11 mm deeper they read as closed.
    const glm::vec3 eyeLocal{0.032f, 0.115f, 0.089f};
    const int leftEye = sk.add("leftEye", head, eyeLocal);
    const int rightEye = sk.add("rightEye", head, {-eyeLocal.x, eyeLocal.y, eyeLocal.z});

    const hand::HandModel handModel = hand::buildHandModel(d.hand);
    struct Arm {
        int shoulder, upper, lower, twistMid;
        HandBones hand;
        glm::vec3 shoulderJoint, wrist;
        glm::mat4 handWorld;
    };
    std::array<Arm, 2> arms{};
    for (hand::Side side : {hand::Side::Left, hand::Side::Right}) {
        const float sx = side == hand::Side::Left ? 1.0f : -1.0f;
        const std::string s = sideName(side);
        Arm& arm = arms[side == hand::Side::Left ? 0 : 1];
        arm.shoulder = sk.add(s + "Shoulder", chest, {sx * 0.04f, 0.11f, 0.0f});
        arm.upper = sk.add(s + "UpperArm", arm.shoulder,
                           glm::vec3(sx * d.shoulderOffsetM.x, d.shoulderOffsetM.y, d.shoulderOffsetM.z) -
                               glm::vec3(sx * 0.04f, 0.11f, 0.0f));
        arm.lower = sk.add(s + "LowerArm", arm.upper, {sx * d.upperArmM, 0.0f, 0.0f});
        arm.twistMid = sk.add(s + "ForearmTwistMid", arm.lower, {sx * d.forearmM * 0.5f, 0.0f, 0.0f});
        arm.hand.forearmTwistWrist = sk.add(s + "ForearmTwistWrist", arm.lower, {sx * d.forearmM, 0.0f, 0.0f});
        // The hand bone's frame is the palm frame (SPEC §1.1) in the T-pose: hand::restFrame.
        const glm::quat palmFrame = hand::restFrame(side);
        arm.hand.hand = sk.add(s + "Hand", arm.lower, {sx * d.forearmM, 0.0f, 0.0f}, palmFrame);
        arm.hand.body[0] = arm.hand.hand;
        const auto bonesInfo = hand::handBones(side);
        const auto rest = hand::restLocalTransforms(handModel, side);
        for (int b = 1; b < hand::kBodyCount; ++b) {
            const int parent = arm.hand.body[bonesInfo[b].parent];
            arm.hand.body[b] = sk.add(std::string(bonesInfo[b].name), parent, rest[b].position * kMmToM,
                                      glm::normalize(rest[b].rotation));
        }
        arm.shoulderJoint = d.chestM + glm::vec3(sx * d.shoulderOffsetM.x, d.shoulderOffsetM.y, d.shoulderOffsetM.z);
        arm.wrist = arm.shoulderJoint + glm::vec3(sx * (d.upperArmM + d.forearmM), 0.0f, 0.0f);
        arm.handWorld = glm::translate(glm::mat4(1.0f), arm.wrist) * glm::mat4_cast(palmFrame) *
                        glm::scale(glm::mat4(1.0f), glm::vec3(kMmToM));
    }
    const int boneCount = static_cast<int>(scene.nodes.size());

    // Skin: every node so far is a joint; joint index = node index.
    render::Skin skin;
    skin.name = "signer";
    skin.skeleton = hips;
    {
        render::Pose rest = render::restPose(scene);
        std::vector<glm::mat4> world;
        render::computeWorldTransforms(scene, rest, world);
        for (int i = 0; i < boneCount; ++i) {
            skin.joints.push_back(i);
            skin.inverseBindMatrices.push_back(glm::inverse(world[i]));
        }
    }

    MeshBuilder mesh;
    // Torso (dark top): superellipse sections from the hips to the shoulders.
    {
        struct Section { float y, halfWidth, halfDepth, z; };
        const std::vector<Section> sections{
            {0.86f, 0.165f, 0.105f, 0.0f},  {0.96f, 0.160f, 0.100f, 0.0f},
            {1.06f, 0.148f, 0.092f, 0.0f},  {1.16f, 0.150f, 0.097f, 0.004f},
            {1.24f, 0.160f, 0.105f, 0.008f}, {1.32f, 0.170f, 0.108f, 0.008f},
            {1.38f, 0.182f, 0.100f, 0.002f}, {1.42f, 0.184f, 0.090f, -0.004f},
            {1.455f, 0.170f, 0.075f, -0.008f}, {1.475f, 0.130f, 0.058f, -0.010f},
            {1.487f, 0.080f, 0.045f, -0.010f}};
        std::vector<Ring> rings;
        for (std::size_t i = 0; i + 1 < sections.size(); ++i) {
            for (int k = 0; k < 3; ++k) {
                const float t = static_cast<float>(k) / 3.0f;
                const Section& a = sections[i];
                const Section& b = sections[i + 1];
                Ring r;
                const float y = a.y + (b.y - a.y) * t;
                r.center = {0.0f, y, a.z + (b.z - a.z) * t};
                r.u = {0, 0, 1};
                r.v = {1, 0, 0};
                r.ru = a.halfDepth + (b.halfDepth - a.halfDepth) * t;
                r.rv = a.halfWidth + (b.halfWidth - a.halfWidth) * t;
                r.exponent = 2.6f;
                const Weights body = Weights::blend(
                    Weights::blend(Weights(hips), Weights(spine), smoothstep(0.96f, 1.12f, y)),
                    Weights(chest), smoothstep(1.16f, 1.30f, y));
                r.weights = body;
                // Shoulder tops follow the upper arms a little (rounded deltoid).
                r.adjust = [body, &arms, y](glm::vec3& p, Weights& w, float, float) {
                    const int armIndex = p.x > 0.0f ? 0 : 1;
                    const float reach = smoothstep(0.13f, 0.18f, std::fabs(p.x)) * smoothstep(1.36f, 1.42f, y);
                    w = Weights::blend(body, Weights(arms[armIndex].upper), 0.35f * reach);
                };
                rings.push_back(r);
            }
        }
        Ring top;
        top.center = {0.0f, sections.back().y, sections.back().z};
        top.u = {0, 0, 1};
        top.v = {1, 0, 0};
        top.ru = sections.back().halfDepth;
        top.rv = sections.back().halfWidth;
        top.exponent = 2.6f;
        top.weights = Weights(chest);
        rings.push_back(top);
        mesh.tube(kTop, rings, 32, 0.0f, 0.004f);
    }
    // Neck (skin) from inside the torso into the head.
    {
        std::vector<Ring> rings;
        for (float y = 1.40f; y <= 1.605f; y += 0.015f) {
            Ring r;
            r.center = {0.0f, y, -0.008f + 0.01f * smoothstep(1.45f, 1.58f, y)};
            r.u = {0, 0, 1};
            r.v = {1, 0, 0};
            r.ru = 0.050f - 0.006f * smoothstep(1.45f, 1.6f, y);
            r.rv = 0.054f - 0.006f * smoothstep(1.45f, 1.6f, y);
            r.weights = Weights::blend(Weights::blend(Weights(chest), Weights(neck), smoothstep(1.42f, 1.48f, y)),
                                       Weights(head), smoothstep(1.52f, 1.58f, y));
            rings.push_back(r);
        }
        mesh.tube(kSkin, rings, 20, 0.0f, 0.0f);
    }
    // Head: a slightly tapered ellipsoid; face features signers read (eyes, brows, mouth).
    {
        const glm::vec3 c = headWorld + glm::vec3(0.0f, 0.10f, 0.012f);  // skull centre
        const glm::mat3 axesYUp(glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
        // Ellipsoid axes: u = x (width), v = -z, w = y (height): rings stack along +y.
        mesh.ellipsoid(kSkin, c, {0.078f, 0.095f, 0.110f}, axesYUp, Weights(head), 28, 22,
                       [](glm::vec3& local) {
                           // Narrower jaw and chin below the cheekbones.
                           const float below = std::clamp(-local.z / 0.110f, 0.0f, 1.0f);
                           local.x *= 1.0f - 0.28f * below * below;
                           local.y *= 1.0f - 0.12f * below * below;
                       });
        const glm::mat3 front(glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1));
        // Hair: a cap over the top and back, leaving the forehead and face clear.
        mesh.ellipsoid(kHair, c + glm::vec3(0.0f, 0.022f, -0.016f), {0.083f, 0.098f, 0.100f},
                       axesYUp, Weights(head), 28, 18, [](glm::vec3& local) {
                           if (local.z < 0.0f) local.z *= 0.55f;  // ends above the ears
                       });
        for (int e = 0; e < 2; ++e) {
            const float sx = e == 0 ? 1.0f : -1.0f;
            const int eyeBone = e == 0 ? leftEye : rightEye;
            const glm::vec3 eye = headWorld + glm::vec3(sx * eyeLocal.x, eyeLocal.y, eyeLocal.z);
            mesh.ellipsoid(kEyeWhite, eye, {0.0125f, 0.0125f, 0.0125f}, front, Weights(eyeBone), 16, 10);
            mesh.ellipsoid(kIris, eye + glm::vec3(0.0f, 0.0f, 0.0095f), {0.0068f, 0.0068f, 0.0042f},
                           front, Weights(eyeBone), 16, 8);
            // Pupil: dark, in front of the iris, turning with it.
            mesh.ellipsoid(kHair, eye + glm::vec3(0.0f, 0.0f, 0.0121f), {0.0029f, 0.0029f, 0.0018f}, front,
                           Weights(eyeBone), 12, 6);
            // Brow: a dark, slightly arched bar above the eye.
            const glm::mat3 browAxes(glm::normalize(glm::vec3(1, sx * -0.12f, 0)), glm::vec3(0, 1, 0),
                                     glm::vec3(0, 0, 1));
            mesh.ellipsoid(kHair, eye + glm::vec3(sx * 0.002f, 0.022f, 0.0f), {0.019f, 0.0042f, 0.006f},
                           glm::mat3(glm::normalize(glm::vec3(1, 0, sx * -0.25f)), browAxes[1],
                                     glm::normalize(glm::cross(glm::normalize(glm::vec3(1, 0, sx * -0.25f)), browAxes[1]))),
                           Weights(head), 12, 8);
            // Ear.
            mesh.ellipsoid(kSkin, c + glm::vec3(sx * 0.077f, -0.012f, -0.004f), {0.010f, 0.027f, 0.016f},
                           front, Weights(head), 12, 8);
        }
        // Nose and mouth.
        mesh.ellipsoid(kSkin, headWorld + glm::vec3(0.0f, 0.085f, 0.097f), {0.0115f, 0.022f, 0.016f}, front,
                       Weights(head), 14, 10);
        mesh.ellipsoid(kLips, headWorld + glm::vec3(0.0f, 0.047f, 0.090f), {0.024f, 0.0068f, 0.0095f}, front,
                       Weights(head), 18, 8);
    }
    // Arms: one continuous sleeve per arm from a round shoulder to the wrist cuff; the skin
    // blends across the elbow and spreads the forearm's twist over two helper bones.
    for (const Arm& arm : arms) {
        const float sx = arm.wrist.x > 0.0f ? 1.0f : -1.0f;
        const glm::vec3 axis{sx, 0.0f, 0.0f};
        const glm::vec3 u{0, 1, 0};
        const glm::vec3 v = glm::cross(axis, u);  // u × v = axis
        const float elbowT = d.upperArmM, wristT = d.upperArmM + d.forearmM;
        const auto radiusAt = [&](float t) {
            const float r0 = 0.050f, rElbow = 0.038f, rForearm = 0.040f, rWrist = 0.029f;
            if (t < elbowT) return r0 + (rElbow - r0) * smoothstep(0.0f, elbowT, t);
            const float f = (t - elbowT) / d.forearmM;
            return f < 0.3f ? rElbow + (rForearm - rElbow) * smoothstep(0.0f, 0.3f, f)
                            : rForearm + (rWrist - rForearm) * smoothstep(0.3f, 1.0f, f);
        };
        const auto weightsAt = [&](float t) {
            const float elbowBlend = smoothstep(elbowT - 0.04f, elbowT + 0.04f, t);
            const float f = std::clamp((t - elbowT) / d.forearmM, 0.0f, 1.0f);
            Weights fore = f < 0.5f ? Weights::blend(Weights(arm.lower), Weights(arm.twistMid), f / 0.5f)
                                    : Weights::blend(Weights(arm.twistMid), Weights(arm.hand.forearmTwistWrist),
                                                     (f - 0.5f) / 0.5f);
            return Weights::blend(Weights(arm.upper), fore, elbowBlend);
        };
        std::vector<Ring> rings;
        const float r0 = radiusAt(0.0f);
        for (int k = 4; k >= 1; --k) {  // round shoulder: a hemisphere about the joint
            const float a = 0.5f * kPi * static_cast<float>(k) / 5.0f;
            Ring r;
            r.center = arm.shoulderJoint - axis * (r0 * std::sin(a));
            r.u = u;
            r.v = v;
            r.ru = r.rv = r0 * std::cos(a);
            r.weights = Weights(arm.upper);
            rings.push_back(r);
        }
        const float cuffT = wristT - 0.012f;
        for (float t = 0.0f; t < cuffT; t += 0.012f) {
            Ring r;
            r.center = arm.shoulderJoint + axis * t;
            r.u = u;
            r.v = v;
            const float rad = radiusAt(t);
            r.ru = rad;
            r.rv = rad * (t > elbowT ? 1.0f - 0.12f * smoothstep(elbowT, wristT, t) : 1.0f);
            r.weights = weightsAt(t);
            rings.push_back(r);
        }
        for (float extra : {0.0f, 0.003f}) {  // cuff: a short flat end
            Ring r;
            r.center = arm.shoulderJoint + axis * (cuffT + extra);
            r.u = u;
            r.v = v;
            r.ru = radiusAt(cuffT) + 0.002f - extra;
            r.rv = r.ru * 0.9f;
            r.weights = weightsAt(cuffT);
            rings.push_back(r);
        }
        mesh.tube(kTop, rings, 20, r0 * (1.0f - std::sin(0.4f * kPi)) + 0.001f, 0.0f);
        // Elbow filler: keeps the inside of a sharply bent elbow from looking hollow.
        mesh.ellipsoid(kTop, arm.shoulderJoint + axis * elbowT, glm::vec3(0.034f), glm::mat3(1.0f),
                       Weights(arm.lower), 16, 10);
        buildHand(mesh, handModel, sx > 0.0f ? hand::Side::Left : hand::Side::Right, arm.handWorld, arm.hand);
    }

    render::Mesh body;
    body.name = "signer";
    body.primitives = mesh.finish();
    scene.meshes.push_back(std::move(body));
    scene.materials = avatarMaterials();
    addSkinToneTexture(scene);
    scene.skins.push_back(std::move(skin));
    render::Node meshNode;
    meshNode.name = "signerMesh";
    meshNode.mesh = 0;
    meshNode.skin = 0;
    scene.nodes.push_back(meshNode);
    scene.roots.push_back(static_cast<int>(scene.nodes.size()) - 1);
    return scene;
}

}  // namespace signstim::signer
