// The default signer's face (issue 23 §2): geometry a face needs to move — brows, eyelids that
// close over the eyeballs, lips that part over a dark mouth opening, a jaw — and its morph
// targets, named with the ARKit-52 blendshape names (signer/avatar_face.hpp). Procedural and
// deterministic like the rest of signer.glb. Every displacement is a smooth function of the
// rest position (and, for the lids and brows, of where on the lid or brow a vertex lies), so
// neighbouring skin follows a moving feature with a falloff instead of tearing from it.
//
// Sizes [D] are chosen for a 1.75 m adult's head (the head ellipsoid of avatar_builder.cpp); the
// excursions at weight 1 are of the order of the extreme action units of FACS (Ekman & Friesen
// 2002): brows ~7 mm, a blink closes the lid fully, the jaw opens ~25 mm at the lips.
#include "signer/avatar_face.hpp"
#include "signer/avatar_mesh.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <functional>

namespace signstim::signer {
namespace avatar_mesh {
namespace {

constexpr float kDeg = kPi / 180.0f;

// Where each part lies on the face, for the targets.
enum class Part { Skin, Nose, UpperLid, LowerLid, Lash, Brow, UpperLip, LowerLip, Mouth, Tongue };
struct PartRange {
    Part part;
    int material;
    std::size_t begin, end;
    float side;                          // +1 the signer's left (+x), -1 right; 0 both
    std::vector<glm::vec2> lidParams{};  // lids, lashes: (azimuth, elevation) in radians per vertex
};

struct Layout {
    glm::vec3 skull;     // centre of the head ellipsoid
    glm::vec3 radii;     // its half-axes: x, y (height), z (depth)
    glm::vec3 eye[2];    // left (+x), right
    glm::vec3 mouth;     // where the lips meet
    glm::vec3 jawPivot;  // the temporomandibular joints' axis (x)
    glm::vec3 nose;
};

// [D] The lids: a shell just outside the eyeball, the opening an almond between the corners.
constexpr float kLidRadiusM = 0.0150f;      // eyeball 12 mm: a closing lid's chord stays outside the cornea
constexpr float kLidInnerDeg = -100.0f;     // the shell reaches behind the skin at both ends
constexpr float kLidOuterDeg = 110.0f;
constexpr float kCornerCentreDeg = -7.0f;   // the opening's centre, a little inward
constexpr float kCornerHalfDeg = 50.0f;     // half the opening's width (22 mm between the corners)
constexpr float kUpperEdgeDeg = 27.0f;      // the upper lid covers the iris's top (iris ~37°)
constexpr float kLowerEdgeDeg = -29.0f;     // the lower lid at the iris's bottom
constexpr float kLidTopDeg = 84.0f;         // the shell's ends near the poles (buried in the skin)
constexpr float kJawOpenDeg = 15.0f;        // [D] ~25 mm at the lips

float openness(float azimuth) {
    const float t = (azimuth / kDeg - kCornerCentreDeg) / kCornerHalfDeg;
    return std::max(0.0f, 1.0f - t * t);
}
float upperEdge(float azimuth) { return kUpperEdgeDeg * kDeg * openness(azimuth); }
float lowerEdge(float azimuth) { return kLowerEdgeDeg * kDeg * openness(azimuth); }

glm::vec3 onLid(glm::vec3 eye, float side, float azimuth, float elevation, float radius) {
    return eye + radius * glm::vec3(side * std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
                                    std::cos(azimuth) * std::cos(elevation));
}

// Where a lid's edge goes for a target (radians), the lid stretching between it and its pole.
struct LidEdges {
    float upper, lower;  // elevation of the upper lid's edge and of the lower lid's edge
};

// The head's skin depth at (x, y) above the jaw (the ellipsoid, front).
float skinZ(const Layout& l, float x, float y) {
    const float a = x / l.radii.x, b = (y - l.skull.y) / l.radii.y;
    return l.skull.z + l.radii.z * std::sqrt(std::max(0.0f, 1.0f - a * a - b * b));
}

glm::vec3 rotateAboutX(glm::vec3 p, glm::vec3 pivot, float angle) {
    const glm::vec3 d = p - pivot;
    const float c = std::cos(angle), s = std::sin(angle);
    return pivot + glm::vec3(d.x, d.y * c - d.z * s, d.y * s + d.z * c);
}

float falloff(float distance, float inner, float outer) { return 1.0f - smoothstep(inner, outer, distance); }

class FaceTargets {
public:
    FaceTargets(const Layout& layout) : l_(layout) {}

    // The displacement of a vertex of `range` at rest position `p` (its index in the range `k`)
    // for target `name`.
    glm::vec3 displacement(const std::string& name, const PartRange& range, std::size_t k, glm::vec3 p) const {
        const Part part = range.part;
        // Sided names: the ARKit "Left" is the face's own left (+x in the body frame).
        float side = 0.0f;
        std::string base = name;
        if (name.size() > 4 && name.compare(name.size() - 4, 4, "Left") == 0) {
            side = 1.0f;
            base = name.substr(0, name.size() - 4);
        } else if (name.size() > 5 && name.compare(name.size() - 5, 5, "Right") == 0) {
            side = -1.0f;
            base = name.substr(0, name.size() - 5);
        }
        if (part == Part::UpperLid || part == Part::LowerLid || part == Part::Lash)
            return lid(base, side, range, k, p);
        if (part == Part::Brow) return brow(base, side, p);
        glm::vec3 d = mouth(base, side, part, p) + cheekAndNose(base, side, part, p);
        if (part == Part::Skin) d += browSkin(base, side, p);
        return d;
    }

private:
    // Lids: each vertex keeps its place between its edge and its pole while the edge moves.
    glm::vec3 lid(const std::string& base, float side, const PartRange& range, std::size_t k, glm::vec3 p) const {
        if (side != 0.0f && side != range.side) return glm::vec3(0.0f);
        const float azimuth = range.lidParams[k].x, elevation = range.lidParams[k].y;
        const float up = upperEdge(azimuth), low = lowerEdge(azimuth), open = openness(azimuth);
        LidEdges to{up, low};
        if (base == "eyeBlink") to.upper = low - 2.0f * kDeg * open;  // closed: over the lower lid's edge
        else if (base == "eyeWide") { to.upper = up + 20.0f * kDeg * open; to.lower = low - 5.0f * kDeg * open; }
        else if (base == "eyeSquint") { to.upper = up - 6.0f * kDeg * open; to.lower = low + 13.0f * kDeg * open; }
        else if (base == "cheekSquint") to.lower = low + 7.0f * kDeg * open;
        // [D] The lids follow the eye's vertical gaze (the eye bones turn the eyeball itself):
        // the upper lid rises with a look up and falls with a look down, the lower lid a little.
        else if (base == "eyeLookUp") { to.upper = up + 8.0f * kDeg * open; to.lower = low + 3.0f * kDeg * open; }
        else if (base == "eyeLookDown") { to.upper = up - 12.0f * kDeg * open; to.lower = low - 2.0f * kDeg * open; }
        else return glm::vec3(0.0f);
        const glm::vec3 eye = l_.eye[range.side > 0.0f ? 0 : 1];
        const float radius = glm::length(p - eye);
        const float top = kLidTopDeg * kDeg;
        float moved = elevation;
        if (range.part == Part::LowerLid) {
            if (low <= -top + 1e-4f) return glm::vec3(0.0f);
            moved = -top + (elevation + top) * (to.lower + top) / (low + top);
        } else {
            if (up >= top - 1e-4f) return glm::vec3(0.0f);
            moved = top - (top - elevation) * (top - to.upper) / (top - up);
        }
        return onLid(eye, range.side, azimuth, moved, radius) - p;
    }

    // Brows: s = 0 at the inner end, 1 at the outer.
    static float browParam(glm::vec3 p) { return std::clamp((std::fabs(p.x) - 0.013f) / 0.040f, 0.0f, 1.0f); }
    glm::vec3 browMove(const std::string& base, float side, float pointSide, float s) const {
        if (side != 0.0f && side != pointSide) return glm::vec3(0.0f);
        if (base == "browInnerUp") return {0.0f, 0.0075f * (1.0f - 0.85f * s), 0.0f};
        if (base == "browOuterUp") return {0.0f, 0.0065f * smoothstep(0.1f, 0.9f, s), 0.0f};
        if (base == "browDown")  // lowered and drawn together (AU 4)
            return {-pointSide * 0.0035f * (1.0f - s), -0.0050f * (1.0f - 0.45f * s), 0.0008f};
        if (base == "eyeWide") return {0.0f, 0.0015f, 0.0f};
        return glm::vec3(0.0f);
    }
    glm::vec3 brow(const std::string& base, float side, glm::vec3 p) const {
        return browMove(base, side, p.x > 0.0f ? 1.0f : -1.0f, browParam(p));
    }
    // The forehead and the skin just under the brow go with it.
    glm::vec3 browSkin(const std::string& base, float side, glm::vec3 p) const {
        const float pointSide = p.x > 0.0f ? 1.0f : -1.0f;
        const float s = browParam(p);
        const float browY = l_.eye[0].y + browRise(s);
        const float dy = p.y - browY;
        const float vertical = dy > 0.0f ? falloff(dy, 0.0f, 0.030f) : 0.5f * falloff(-dy, 0.0f, 0.006f);
        const float across = falloff(std::fabs(p.x), 0.050f, 0.068f) * smoothstep(0.045f, 0.075f, p.z - l_.skull.z + 0.06f);
        const float w = vertical * across;
        if (w <= 0.0f) return glm::vec3(0.0f);
        glm::vec3 d = w * browMove(base, side, pointSide, s);
        // Frowning gathers the skin between the brows (the inner ends meet less than the brows).
        if (base == "browDown" && std::fabs(p.x) < 0.013f) d.x *= std::fabs(p.x) / 0.013f;
        return d;
    }

  public:
    static float browRise(float s) { return 0.0185f + 0.0050f * (1.0f - ((s - 0.6f) / 0.6f) * ((s - 0.6f) / 0.6f)); }

  private:
    // How much of the jaw's turn a point of the skin takes: below the line from the mouth's
    // corners back to the jaw joints, fading over a few millimetres.
    float jawness(glm::vec3 p) const {
        const float back = std::clamp((l_.mouth.z - 0.010f - p.z) / (l_.mouth.z - 0.010f - l_.jawPivot.z), 0.0f, 1.0f);
        const float lineY = l_.mouth.y + (l_.jawPivot.y - 0.012f - l_.mouth.y) * back;
        return smoothstep(lineY + 0.004f, lineY - 0.004f, p.y) * smoothstep(l_.jawPivot.z - 0.03f, l_.jawPivot.z + 0.01f, p.z);
    }
    float mouthRegion(glm::vec3 p) const {
        const float r = std::hypot(p.x - l_.mouth.x, 1.3f * (p.y - l_.mouth.y));
        return falloff(r, 0.020f, 0.045f) * smoothstep(0.04f, 0.07f, p.z - l_.skull.z + 0.03f);
    }
    glm::vec3 mouth(const std::string& base, float side, Part part, glm::vec3 p) const {
        const bool lip = part == Part::UpperLip || part == Part::LowerLip;
        const bool upper = part == Part::UpperLip || (part == Part::Mouth && p.y >= l_.mouth.y - 0.001f);
        const float u = std::clamp((p.x - l_.mouth.x) / 0.0235f, -1.0f, 1.0f);
        const glm::vec3 rel = p - l_.mouth;
        // The jaw carries the lower lip, the lower half of the mouth's opening, the tongue and
        // the chin; its turn about the joints' axis, at full weight.
        const float jaw = part == Part::LowerLip || part == Part::Tongue ? 1.0f
                          : part == Part::Mouth ? smoothstep(l_.mouth.y + 0.001f, l_.mouth.y - 0.003f, p.y)
                          : part == Part::Skin ? jawness(p)
                          : 0.0f;
        if (base == "jawOpen") return jaw * (rotateAboutX(p, l_.jawPivot, kJawOpenDeg * kDeg) - p);
        if (base == "mouthClose") {  // the lips meet with the jaw open (ARKit: used with jawOpen)
            if (part == Part::LowerLip || part == Part::Tongue || (part == Part::Mouth && !upper))
                return jaw * (rotateAboutX(p, l_.jawPivot, -kJawOpenDeg * kDeg) - p);
            return glm::vec3(0.0f);
        }
        if (base == "tongueOut") return part == Part::Tongue ? glm::vec3(0.0f, 0.002f, 0.018f) : glm::vec3(0.0f);
        const float region = lip || part == Part::Mouth || part == Part::Tongue ? 1.0f : part == Part::Skin ? mouthRegion(p) : 0.0f;
        if (region <= 0.0f) return glm::vec3(0.0f);
        if (base == "mouthFunnel") {  // lips forward and apart, a round opening
            const float open = part == Part::Tongue ? 0.0f : (upper ? 0.0028f : -0.0032f) * (1.0f - u * u);
            return region * glm::vec3(-0.22f * rel.x, lip || part == Part::Mouth ? open : 0.0f,
                                      (lip ? 0.005f : 0.003f) * (1.0f - 0.3f * u * u));
        }
        if (base == "mouthPucker") {  // lips forward and together, corners drawn in
            return region * glm::vec3(-0.35f * rel.x, lip ? (upper ? -0.0005f : 0.0005f) : 0.0f,
                                      (lip || part == Part::Mouth ? 0.0075f : 0.0045f) * (1.0f - 0.3f * u * u));
        }
        if (base == "mouthRollLower")
            return part == Part::LowerLip ? glm::vec3(0.0f, 0.0015f, -0.004f) : glm::vec3(0.0f);
        if (base == "mouthRollUpper")
            return part == Part::UpperLip ? glm::vec3(0.0f, -0.0015f, -0.004f) : glm::vec3(0.0f);
        if (base == "mouthShrugUpper")  // the upper lip pushed up and out
            return part == Part::UpperLip ? glm::vec3(0.0f, 0.0015f, 0.0015f) : glm::vec3(0.0f);
        if (base == "mouthShrugLower") {  // the chin raised (AU 17): the lower lip pushed up and out, the chin with it
            if (part == Part::LowerLip) return {0.0f, 0.0025f, 0.0015f};
            if (part == Part::Skin && p.y < l_.mouth.y - 0.006f) return 0.6f * region * jawness(p) * glm::vec3(0.0f, 0.0025f, 0.001f);
            return glm::vec3(0.0f);
        }
        if (side == 0.0f) return glm::vec3(0.0f);
        // Sided shapes: the corner on that side moves; the lips follow toward it.
        const glm::vec3 corner = l_.mouth + glm::vec3(side * 0.024f, 0.0f, -0.004f);
        const float toward = lip || part == Part::Mouth ? std::pow(smoothstep(0.0f, 1.0f, side * u), 1.5f)
                                                        : falloff(glm::length(p - corner), 0.004f, 0.030f);
        const float half = lip ? smoothstep(-0.6f, 0.6f, side * u) : 0.0f;
        if (base == "mouthSmile") return toward * glm::vec3(side * 0.004f, 0.0055f, -0.003f);
        if (base == "mouthFrown") return toward * glm::vec3(0.0f, -0.005f, -0.0005f);
        if (base == "mouthStretch") return toward * glm::vec3(side * 0.006f, -0.0015f, -0.002f);
        if (base == "mouthDimple") return toward * glm::vec3(side * 0.002f, 0.0005f, -0.0035f);  // the corner drawn back
        if (base == "mouth")  // mouthLeft/Right: the closed mouth pulled toward that side
            return (lip || part == Part::Mouth || part == Part::Tongue ? 1.0f : 0.6f) * region * glm::vec3(side * 0.005f, 0.0f, 0.0f);
        if (base == "mouthLowerDown" && (part == Part::LowerLip || (part == Part::Mouth && !upper)))
            return smoothstep(-0.5f, 0.5f, side * u) * glm::vec3(0.0f, -0.003f, 0.0005f);
        if (base == "mouthPress")
            return half * glm::vec3(0.0f, part == Part::UpperLip ? -0.0015f : 0.0018f, -0.0015f);
        if (base == "mouthUpperUp") {
            if (part == Part::UpperLip) return smoothstep(-0.5f, 0.5f, side * u) * glm::vec3(0.0f, 0.0035f, 0.001f);
            if (part == Part::Skin && p.y > l_.mouth.y + 0.006f && p.y < l_.nose.y - 0.01f)
                return 0.6f * falloff(glm::length(p - (corner + glm::vec3(-side * 0.01f, 0.012f, 0.0f))), 0.004f, 0.02f) *
                       glm::vec3(0.0f, 0.0035f, 0.001f);
        }
        return glm::vec3(0.0f);
    }
    glm::vec3 cheekAndNose(const std::string& base, float side, Part part, glm::vec3 p) const {
        if (base == "cheekPuff") {
            if (part == Part::UpperLip || part == Part::LowerLip) return {0.0f, 0.0f, 0.0015f};
            if (part != Part::Skin) return glm::vec3(0.0f);
            glm::vec3 d(0.0f);
            for (float s : {1.0f, -1.0f}) {
                const float r = std::hypot(p.x - s * 0.040f, p.y - (l_.mouth.y + 0.008f));
                const float w = falloff(r, 0.006f, 0.032f) * smoothstep(0.02f, 0.06f, p.z - l_.skull.z + 0.03f);
                const glm::vec3 out = glm::normalize(glm::vec3(p.x, 0.0f, p.z - l_.skull.z + 0.02f));
                d += 0.011f * w * out;
            }
            return d;
        }
        if (side == 0.0f) return glm::vec3(0.0f);
        if (base == "cheekSquint" && part == Part::Skin) {
            const glm::vec3 e = l_.eye[side > 0.0f ? 0 : 1];
            const float r = std::hypot(p.x - e.x, p.y - (e.y - 0.022f));
            return falloff(r, 0.004f, 0.022f) * smoothstep(0.04f, 0.07f, p.z - l_.skull.z + 0.03f) *
                   glm::vec3(0.0f, 0.003f, 0.001f);
        }
        if (base == "noseSneer") {
            if (part == Part::Nose) {
                const float w = smoothstep(-0.2f, 1.0f, side * (p.x - l_.nose.x) / 0.0115f) *
                                smoothstep(l_.nose.y + 0.01f, l_.nose.y - 0.01f, p.y);
                return w * glm::vec3(0.0f, 0.003f, 0.0f);
            }
            if (part == Part::Skin) {
                const float r = std::hypot(p.x - side * 0.015f, p.y - (l_.nose.y - 0.008f));
                return falloff(r, 0.004f, 0.020f) * smoothstep(0.05f, 0.08f, p.z - l_.skull.z + 0.03f) *
                       glm::vec3(0.0f, 0.0025f, 0.0f);
            }
            if (part == Part::UpperLip) return smoothstep(-0.3f, 0.6f, side * (p.x - l_.mouth.x) / 0.0235f) * glm::vec3(0.0f, 0.001f, 0.0f);
        }
        return glm::vec3(0.0f);
    }

    Layout l_;
};

}  // namespace

render::Mesh buildFaceMesh(const glm::vec3& headWorld, const glm::vec3& eyeLocal, int headBone) {
    Layout l;
    l.skull = headWorld + glm::vec3(0.0f, 0.10f, 0.012f);
    l.radii = {0.078f, 0.110f, 0.095f};
    l.eye[0] = headWorld + eyeLocal;
    l.eye[1] = headWorld + glm::vec3(-eyeLocal.x, eyeLocal.y, eyeLocal.z);
    l.mouth = headWorld + glm::vec3(0.0f, 0.047f, 0.090f);
    l.jawPivot = headWorld + glm::vec3(0.0f, 0.085f, -0.004f);
    l.nose = headWorld + glm::vec3(0.0f, 0.085f, 0.097f);
    const Weights head(headBone);

    MeshBuilder mesh;
    std::vector<PartRange> parts;
    const auto record = [&](Part part, int material, float side, const std::function<void()>& build) {
        const std::size_t begin = mesh.primitive(material).vertices.size();
        build();
        parts.push_back({part, material, begin, mesh.primitive(material).vertices.size(), side});
        return &parts.back();
    };

    // The head's skin: a slightly tapered ellipsoid (finer than the body, for the face's falloffs).
    const glm::mat3 axesYUp(glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), glm::vec3(0, 1, 0));
    record(Part::Skin, kSkin, 0.0f, [&] {
        mesh.ellipsoid(kSkin, l.skull, {l.radii.x, l.radii.z, l.radii.y}, axesYUp, head, 44, 34, [](glm::vec3& local) {
            // Cheekbones and the orbits' outer rims: the face's sides beside the eyes come forward
            // (a face is flatter than an ellipsoid), so in a three-quarter view the far eye lies
            // inside the outline (issue 21). Only outside the lids (|x| > 46 mm), not over them.
            if (local.y < 0.0f) {
                const float ax = std::fabs(local.x);
                const float beside = smoothstep(0.046f, 0.060f, ax) * (1.0f - smoothstep(0.068f, 0.078f, ax));
                const float level = smoothstep(-0.065f, -0.030f, local.z) * (1.0f - smoothstep(0.030f, 0.060f, local.z));
                local.y -= 0.010f * beside * level;
            }
            // Narrower jaw and chin below the cheekbones.
            const float below = std::clamp(-local.z / 0.110f, 0.0f, 1.0f);
            local.x *= 1.0f - 0.28f * below * below;
            local.y *= 1.0f - 0.12f * below * below;
        });
    });
    const glm::mat3 front(1.0f);
    record(Part::Nose, kSkin, 0.0f, [&] {
        mesh.ellipsoid(kSkin, l.nose, {0.0115f, 0.022f, 0.016f}, front, head, 14, 10);
        // The bridge between the eyes, standing ~13 mm in front of the corneas: it hides the
        // far eye in a three-quarter view as a face does (the eyes inside the outline, issue 21).
        mesh.ellipsoid(kSkin, l.nose + glm::vec3(0.0f, 0.024f, 0.004f), {0.0078f, 0.020f, 0.0085f}, front, head, 12, 10);
    });

    for (int e = 0; e < 2; ++e) {
        const float sx = e == 0 ? 1.0f : -1.0f;
        const glm::vec3 eye = l.eye[e];
        // Lids: (azimuth, elevation) rows from the edge to the pole.
        constexpr int kAcross = 26, kRows = 9;
        const auto lid = [&](Part part, int material, float radius, float fromDeg, float toDeg) {
            std::vector<std::vector<glm::vec3>> rows;
            std::vector<glm::vec2> params;
            for (int i = 0; i < kRows; ++i) {
                std::vector<glm::vec3> row;
                for (int j = 0; j <= kAcross; ++j) {
                    const float a = (fromDeg + (toDeg - fromDeg) * static_cast<float>(j) / kAcross) * kDeg;
                    const float t = static_cast<float>(i) / (kRows - 1);
                    float elevation = 0.0f;
                    if (part == Part::UpperLid) elevation = upperEdge(a) + (kLidTopDeg * kDeg - upperEdge(a)) * t * t;
                    else if (part == Part::LowerLid) elevation = lowerEdge(a) - (kLidTopDeg * kDeg + lowerEdge(a)) * t * t;
                    else elevation = upperEdge(a) - 0.3f * kDeg + 4.5f * kDeg * t * openness(a);  // lash line
                    row.push_back(onLid(eye, sx, a, elevation, radius));
                    params.emplace_back(a, elevation);
                }
                rows.push_back(std::move(row));
            }
            PartRange* range = record(part, material, sx, [&] { mesh.grid(material, rows, head, eye); });
            range->lidParams = std::move(params);
        };
        lid(Part::UpperLid, kSkin, kLidRadiusM, kLidInnerDeg, kLidOuterDeg);
        lid(Part::LowerLid, kSkin, kLidRadiusM, kLidInnerDeg, kLidOuterDeg);
        lid(Part::Lash, kHair, kLidRadiusM + 0.0004f, kCornerCentreDeg - kCornerHalfDeg, kCornerCentreDeg + kCornerHalfDeg);

        // Brow: a dark bar on the skin, arched, thinning outward.
        record(Part::Brow, kHair, sx, [&] {
            std::vector<Ring> rings;
            constexpr int kRings = 14;
            for (int i = 0; i <= kRings; ++i) {
                const float s = static_cast<float>(i) / kRings;
                const float x = sx * (0.013f + 0.040f * s);
                const float y = eye.y + FaceTargets::browRise(s);
                Ring r;
                r.center = {x, y, skinZ(l, x, y) + 0.0008f};
                r.u = {0.0f, 1.0f, 0.0f};
                r.v = {0.0f, 0.0f, sx};
                // Thick at the head, thinning to the tail; both ends rounded.
                r.ru = (0.0034f - 0.0016f * s) * (0.35f + 0.65f * smoothstep(0.0f, 0.15f, s) * smoothstep(1.0f, 0.85f, s));
                r.rv = 0.0022f;
                r.weights = head;
                rings.push_back(r);
            }
            mesh.tube(kHair, rings, 12, 0.001f, 0.001f);
        });
    }

    // Lips over a dark opening; the tongue behind them.
    record(Part::UpperLip, kLips, 0.0f, [&] {
        mesh.ellipsoid(kLips, l.mouth + glm::vec3(0.0f, 0.0042f, 0.0005f), {0.0235f, 0.0046f, 0.0085f}, front, head, 24, 10);
    });
    record(Part::LowerLip, kLips, 0.0f, [&] {
        mesh.ellipsoid(kLips, l.mouth + glm::vec3(0.0f, -0.0048f, 0.0f), {0.0215f, 0.0054f, 0.0090f}, front, head, 24, 10);
    });
    record(Part::Mouth, kMouth, 0.0f, [&] {
        mesh.ellipsoid(kMouth, l.mouth + glm::vec3(0.0f, -0.001f, -0.004f), {0.0195f, 0.0035f, 0.008f}, front, head, 20, 12);
    });
    record(Part::Tongue, kLips, 0.0f, [&] {
        mesh.ellipsoid(kLips, l.mouth + glm::vec3(0.0f, -0.0035f, -0.006f), {0.013f, 0.0035f, 0.009f}, front, head, 16, 8);
    });

    render::Mesh out;
    out.name = "signerFace";
    std::vector<int> materials;
    out.primitives = mesh.finish();
    const FaceTargets targets(l);
    const std::vector<std::string>& names = faceTargetNames();
    for (render::Primitive& prim : out.primitives) {
        for (const std::string& name : names) {
            render::MorphTarget target;
            target.position.assign(prim.vertices.size(), glm::vec3(0.0f));
            for (const PartRange& range : parts) {
                if (range.material != prim.material) continue;
                for (std::size_t v = range.begin; v < range.end; ++v)
                    target.position[v] = targets.displacement(name, range, v - range.begin, prim.vertices[v].position);
            }
            // Falloff tails under a micrometre are none (the file stores only what moves).
            for (glm::vec3& d : target.position)
                if (glm::length(d) < 1e-6f) d = glm::vec3(0.0f);
            // Normals of the shape at weight 1, as displacements of the rest normals.
            render::Primitive moved = prim;
            for (std::size_t v = 0; v < moved.vertices.size(); ++v) moved.vertices[v].position += target.position[v];
            MeshBuilder::computeNormals(moved);
            target.normal.resize(prim.vertices.size());
            bool turns = false;
            for (std::size_t v = 0; v < moved.vertices.size(); ++v) {
                target.normal[v] = moved.vertices[v].normal - prim.vertices[v].normal;
                if (glm::length(target.normal[v]) < 1e-3f) target.normal[v] = glm::vec3(0.0f);  // < 0.06°
                turns = turns || target.normal[v] != glm::vec3(0.0f);
            }
            if (!turns) target.normal.clear();  // no NORMAL attribute (a smaller file)
            prim.targets.push_back(std::move(target));
        }
    }
    out.targetNames = names;
    out.weights.assign(names.size(), 0.0f);
    return out;
}

}  // namespace avatar_mesh
}  // namespace signstim::signer
