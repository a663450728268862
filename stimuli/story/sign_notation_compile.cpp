// Compiling a sign's notation to keyframes (docs/lexicon.md, "How a sign is compiled"): the
// places resolved (body locations, points of the other hand by the hand model), each stroke
// sampled along its path with the inner samples passed through (sampleTrack), circles closed,
// repetitions returned as their mode says, the other hand mirrored, alternating or held as the
// base, and every contact turned into an event at its moment.
#include "stimuli/story/sign_notation.hpp"

#include "hand/contact.hpp"
#include "stimuli/story/lexicon.hpp"
#include "stimuli/verbs/sora.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace signstim::stimuli {
namespace {

constexpr double kPi = 3.14159265358979323846;
// [D] Samples of a curved stroke: 12 a circle (30° turns, which the hand passes at cos² 30° =
// 75 % of its chord speed, sampleTrack), 6 an arc, 12 a wavy path.
constexpr int kCircleSamples = 12, kArcSamples = 6, kWavySamples = 12;
// [D] An arc bulges by 15 % of its chord (at least 15 mm), a zigzag or wave by 15 %.
constexpr double kArcBulge = 0.15, kArcMinimumBulgeMm = 15.0, kZigzagWidth = 0.15;
// [D] A zigzag has two corners (a Z), each 12 % of the chord to alternate sides: the turn at a
// corner is 55° (segments (1/3, 0.12) and (1/3, −0.24) of the chord), under the 90° at which
// sampleTrack stops the hand.
constexpr int kZigzagCorners = 2;
constexpr double kZigzagCornerWidth = 0.12;
// [D] A lifted return takes 60 % of the stroke's time and clears the surface by 30 % of the
// stroke's length (at least 15 mm): the quick return of a tap (issue 22: "quick lifted return").
constexpr double kLiftedReturnTime = 0.6, kLiftedHeight = 0.3, kLiftedMinimumMm = 15.0;
// [D] A flick opens in the first 35 % of its stroke (a snap), the rest held open.
constexpr double kFlickShare = 0.35;
// [D] A straight stroke of hands moving together whose orientation turns: 4 keys (a 20° turn
// keeps the left hand within 0.1 mm of its rigid pose between them).
constexpr int kTogetherTurnSamples = 4;
// [D] A rub moves 8 mm to each side.
constexpr double kRubMm = 8.0;
// [D] A turn of the hand wider than this (a flip: COOK's palm down to palm up, half a turn) may
// go either way round, the longer way at most 210°; narrower, the shortest way is the one a
// forearm takes (BAD's 125° from the chin down and out).
constexpr double kWideTurnRad = 150.0 * kPi / 180.0;
// [D] Two ways of a wide turn whose middles are closer than this go the same way round (the
// two ways round a half turn are 180° apart halfway; BAD's, a swing and a twist, 70°).
constexpr double kSameWayRad = 45.0 * kPi / 180.0;

// The orientation `u` (0..1) of the way from `q0` to `q1` that a right forearm turns (the
// notation's orientations are the right hand's; the left hand mirrors them). Within kWideTurnRad
// the shortest way. A wider turn is what a signer makes as a swing of the fingers' direction (the
// shortest, at one pace) and a twist about the fingers, the twist going the way whose midpoint
// has the palm toward the body's midline and the chest (left and back): through the forearm's
// neutral rotation (thumb up; hand/arm_ik.hpp: about 90° of pronation or supination each side of
// it), as a signer flips the hand, never round the other way through the limits (COOK's palm
// facing out halfway asked the forearm to pronate 180°; BAD's and HOT's palm, toward the face at
// first, turns down or out by pronating through neutral).
glm::dquat forearmTurn(const glm::dquat& q0, const glm::dquat& q1, double u) {
    if (u <= 0.0) return q0;
    if (u >= 1.0) return q1;
    if (rotationAngleBetween(q0, q1) <= kWideTurnRad) return slerpShortest(q0, q1, u);
    const glm::dvec3 f0 = fingersDirection(q0), f1 = fingersDirection(q1);
    const glm::dvec3 across = glm::cross(f0, f1);
    const double swing = std::atan2(glm::length(across), glm::dot(f0, f1));
    const glm::dvec3 swingAxis = glm::length(across) > 1e-9 ? glm::normalize(across) : glm::dvec3(0.0, 1.0, 0.0);
    // The twist left after the whole swing: the palm's turn about the end's fingers.
    const glm::dvec3 swungPalm = glm::angleAxis(swing, swingAxis) * palmDirection(q0), p1 = palmDirection(q1);
    const double twist = std::atan2(glm::dot(glm::cross(swungPalm, p1), f1), glm::dot(swungPalm, p1));
    const auto along = [&](double t, double turn) {
        const glm::dquat swung = glm::angleAxis(t * swing, swingAxis) * q0;
        return glm::normalize(glm::angleAxis(t * turn, fingersDirection(swung)) * swung);
    };
    const double otherWay = twist > 0.0 ? twist - 2.0 * kPi : twist + 2.0 * kPi;
    const glm::dvec3 neutralPalm = glm::normalize(glm::dvec3(-1.0, 0.0, -0.6));
    const double turn = glm::dot(palmDirection(along(0.5, otherWay)), neutralPalm) >
                                glm::dot(palmDirection(along(0.5, twist)), neutralPalm)
                            ? otherWay
                            : twist;
    // Where the shortest slerp already goes this way round (its middle within kSameWayRad of this
    // one's), it is kept: the same motion, to the bit, as before this rule (AGAIN, HOW).
    if (rotationAngleBetween(slerpShortest(q0, q1, 0.5), along(0.5, turn)) < kSameWayRad) return slerpShortest(q0, q1, u);
    return along(u, turn);
}

glm::dvec3 mirror(const glm::dvec3& v) { return {-v.x, v.y, v.z}; }

glm::dquat mirror(const glm::dquat& q) {
    return orientationFromFingersPalm(mirror(fingersDirection(q)), mirror(palmDirection(q)));
}

// One sample of a stroke: where the palm origin is at u (0..1 of the stroke), and whether the
// hand passes through it.
struct Sample {
    double u = 0.0;
    glm::dvec3 position{0.0};
    bool via = false;
};

class Compiler {
public:
    Compiler(const SignNotation& n, const std::map<std::string, glm::dvec3>& locations, const HandshapeLibrary& shapes,
             const hand::HandModel& model, const JsonSource& source, const std::string& pointer)
        : n_(n), locations_(locations), shapes_(shapes), model_(model), source_(source), pointer_(pointer) {}

    CompiledNotation compile() {
        const bool twoHands = n_.twoHanded();
        out_.hands = twoHands ? std::vector<HandSide>{HandSide::Right, HandSide::Left} : std::vector<HandSide>{HandSide::Right};
        out_.keyframes.resize(out_.hands.size());
        out_.passThrough.resize(out_.hands.size());
        bool anyBase = false, anyBaseHand = false;
        for (const NotationPart& p : n_.parts) {
            anyBase = anyBase || p.hands == HandRelation::Base;
            anyBaseHand = anyBaseHand || !p.baseHandshape.empty();
        }
        if (anyBase && !anyBaseHand)
            source_.failAt(pointer_ + "/notation/parts/0/base", "a part with \"hands\": \"base\" needs a base hand in a part");
        double t = 0.0;
        for (std::size_t i = 0; i < n_.parts.size(); ++i) {
            part_ = static_cast<int>(i);
            partPointer_ = pointer_ + "/notation/parts/" + std::to_string(i);
            t += n_.parts[i].transitionSeconds;
            compilePart(n_.parts[i], t);
            t += n_.parts[i].seconds;
        }
        if (twoHands) holdLeftInOneHandedParts();
        for (const ContactEvent& e : out_.contacts) {
            const bool onHand = e.at.rfind("hand:", 0) == 0 || e.at.rfind("arm:", 0) == 0;
            (onHand ? out_.contact.hands : out_.contact.body) = true;
        }
        for (const NotationPart& p : n_.parts) out_.contact.clasp = out_.contact.clasp || p.clasp;
        return std::move(out_);
    }

private:
    const hand::HandControls& controls(const std::string& shape) const { return shapes_.at(shape).controls; }

    glm::dvec3 point(const std::string& shape, hand::Side side, const std::string& name, const std::string& field) const {
        const std::optional<glm::dvec3> p = handPointMm(model_, controls(shape), side, name);
        if (!p) {
            std::string known;
            for (const std::string& k : handPointNames()) known += (known.empty() ? "" : ", ") + k;
            source_.failAt(field, "unknown hand point '" + name + "' (known: " + known + ")");
        }
        return *p;
    }

    // The part whose base hand holds in `part`: its own; else the next part's (the base hand
    // waits where it is needed); else, after the last part with one, the previous part's (the
    // still hand stays where it was). -1: no part has a base hand.
    int basePart(std::size_t part) const {
        for (std::size_t i = part; i < n_.parts.size(); ++i)
            if (!n_.parts[i].baseHandshape.empty()) return static_cast<int>(i);
        for (std::size_t i = std::min(part, n_.parts.size()); i-- > 0;)
            if (!n_.parts[i].baseHandshape.empty()) return static_cast<int>(i);
        return -1;
    }

    // The base hand's pose in `part` (basePart).
    std::optional<HandPose> basePose(std::size_t part) const {
        const int i = basePart(part);
        if (i >= 0) {
            const NotationPart& p = n_.parts[static_cast<std::size_t>(i)];
            const glm::dquat q = orientationFromFingersPalm(p.baseFingers, p.basePalm);
            const glm::dvec3 palm = point(p.baseHandshape, hand::Side::Left, "palm", "");
            HandPose pose;
            pose.orientation = q;
            pose.positionMm = palmOriginForTouch(body(p.baseAt, partPointer_ + "/base/at"), q, palm);
            return pose;
        }
        return std::nullopt;
    }

    glm::dvec3 body(const NotationPlace& place, const std::string& field) const {
        const auto found = locations_.find(place.name);
        if (found == locations_.end()) {
            std::string known;
            for (const auto& l : locations_) known += (known.empty() ? "" : ", ") + l.first;
            source_.failAt(field, "unknown place '" + place.name + "' (body locations: " + known +
                                      "; on the other hand: hand:palm, hand:back, ...)");
        }
        return found->second + place.offsetMm;
    }

    // A place in signing space: a body location, or a point of the base hand in this part.
    glm::dvec3 resolve(const NotationPlace& place, const std::string& field) const {
        if (!place.onOtherHand()) return body(place, field);
        if (const NotationPart& part = n_.parts[static_cast<std::size_t>(part_)]; part.hands == HandRelation::Mirrored || part.hands == HandRelation::Symmetric) {
            // Mirrored hands meet on the midline, where each hand's point is the other's mirror
            // image (MORE; FAMILY's thumbs, then little fingers): "hand:P" is the midline at the
            // height and depth of "neutral" plus the offset, whose x keeps the point that far
            // from the midline. The right hand's point P is put there (compilePart), the left's
            // mirrors it.
            NotationPlace neutral{"neutral", glm::dvec3(0.0)};
            glm::dvec3 at = body(neutral, field) + place.offsetMm;
            at.x = place.offsetMm.x;
            return at;
        }
        const NotationPart& current = n_.parts[static_cast<std::size_t>(part_)];
        const bool isBase = current.hands == HandRelation::Base || current.hands == HandRelation::Together;
        std::optional<HandPose> base = isBase ? basePose(static_cast<std::size_t>(part_)) : std::nullopt;
        if (!base) source_.failAt(field, "a place on the other hand needs \"hands\": \"base\" or \"together\" and the part's base hand");
        // A base hand with its own path: the path's end is on the base hand where it has moved to.
        base->positionMm += baseShiftMm_;
        const std::string name = place.name.substr(place.name.find(':') + 1);
        const std::string& shape = n_.parts[static_cast<std::size_t>(part_)].baseHandshape.empty()
                                       ? baseShapeFrom(static_cast<std::size_t>(part_))
                                       : n_.parts[static_cast<std::size_t>(part_)].baseHandshape;
        return handPointInSpace(*base, point(shape, hand::Side::Left, name, field)) + place.offsetMm;
    }

    const std::string& baseShapeFrom(std::size_t part) const {
        const int i = basePart(part);
        return n_.parts[static_cast<std::size_t>(std::max(i, 0))].baseHandshape;
    }

    // The stroke's samples from start to end (palm origins).
    std::vector<Sample> stroke(const NotationPart& p, const glm::dvec3& start, const glm::dvec3& end) const {
        std::vector<Sample> s;
        const glm::dvec3 chord = end - start;
        const double length = glm::length(chord);
        switch (p.path) {
            case PathShape::None:
            case PathShape::Straight:
                s = {{0.0, start, false}, {1.0, end, false}};
                // Hands moving together that turn as they go: the left hand swings on an arc
                // about the right, which keys passed through keep (a chord would pull it ~1 mm
                // out of the rigid pose for a 20° turn).
                if (p.hands == HandRelation::Together && p.endFingers && p.local != LocalMovement::Flick && length > 0.0)
                    for (int k = kTogetherTurnSamples - 1; k > 0; --k) {
                        const double u = static_cast<double>(k) / kTogetherTurnSamples;
                        s.insert(s.begin() + 1, {u, start + u * chord, true});
                    }
                // A flick snaps open early: a key where it is open (passed through).
                if (p.local == LocalMovement::Flick) s.insert(s.begin() + 1, {kFlickShare, start + kFlickShare * chord, length > 0.0});
                break;
            case PathShape::Arc: {
                const double bulge = p.bulgeMm > 0.0 ? p.bulgeMm : std::max(kArcMinimumBulgeMm, kArcBulge * length);
                for (int k = 0; k <= kArcSamples; ++k) {
                    const double u = static_cast<double>(k) / kArcSamples;
                    s.push_back({u, start + u * chord + p.side * bulge * std::sin(kPi * u), k > 0 && k < kArcSamples});
                }
                break;
            }
            case PathShape::Circle: {
                const double r = 0.5 * p.sizeMm;
                const glm::dvec3 centre = start - r * p.side;
                for (int k = 0; k <= kCircleSamples; ++k) {
                    const double u = static_cast<double>(k) / kCircleSamples, a = 2.0 * kPi * u;
                    // The last sample is the first: the circle closes exactly.
                    const glm::dvec3 at = k == kCircleSamples ? start : centre + r * (p.side * std::cos(a) + p.direction * std::sin(a));
                    s.push_back({u, at, k > 0 && k < kCircleSamples});
                }
                break;
            }
            case PathShape::Zigzag: {
                // A zigzag is one path movement whose shape turns (Brentari 1998: a path
                // feature of one movement; Liddell & Johnson 1989: no hold inside a movement
                // segment), so its corners are via points the hand turns through without a
                // hold. The turns stay under 90° (cos² slows the hand to ~1/3 of its chord
                // speed, sampleTrack) — a sharper one would be a reversal, which stops.
                for (int k = 0; k <= kZigzagCorners + 1; ++k) {
                    const double u = static_cast<double>(k) / (kZigzagCorners + 1);
                    const bool corner = k > 0 && k <= kZigzagCorners;
                    const double lateral = corner ? (k % 2 ? 1.0 : -1.0) * kZigzagCornerWidth * length : 0.0;
                    s.push_back({u, start + u * chord + p.side * lateral, corner && length > 0.0});
                }
                break;
            }
            case PathShape::Wavy:
                for (int k = 0; k <= kWavySamples; ++k) {
                    const double u = static_cast<double>(k) / kWavySamples;
                    s.push_back({u, start + u * chord + p.side * kZigzagWidth * length * std::sin(4.0 * kPi * u),
                                 k > 0 && k < kWavySamples});
                }
                break;
        }
        // A curved stroke's keys are timed by the distance along it, so the hand keeps one speed
        // between its ends: sampled evenly in u, an arc whose side leans along its chord (MARRY:
        // up while the chord goes down) has short first and long last spans, and keys evenly
        // spaced in time made the hand creep off and then rush (16 mm in the first sixth, 38 mm
        // in the last).
        if (p.path == PathShape::Arc || p.path == PathShape::Zigzag || p.path == PathShape::Wavy) {
            double along = 0.0;
            std::vector<double> at{0.0};
            for (std::size_t k = 1; k < s.size(); ++k) at.push_back(along += glm::distance(s[k].position, s[k - 1].position));
            if (along > 1e-6)
                for (std::size_t k = 0; k < s.size(); ++k) s[k].u = at[k] / along;
        }
        return s;
    }

    void key(int hand, double t, const HandPose& pose, const std::string& shape, bool via) {
        std::vector<VerbKeyframe>& keys = out_.keyframes[static_cast<std::size_t>(hand)];
        std::vector<bool>& flags = out_.passThrough[static_cast<std::size_t>(hand)];
        VerbKeyframe k;
        k.timeSeconds = t;
        k.pose = pose;
        k.handshape = shape;
        if (!keys.empty() && t <= keys.back().timeSeconds + 1e-9) {
            // The same moment as the last key (a part that starts where the last ended): replaced.
            keys.back() = k;
            flags.back() = via;
            return;
        }
        keys.push_back(k);
        flags.push_back(via);
    }

    void compilePart(const NotationPart& p, double t0) {
        const glm::dquat q0 = orientationFromFingersPalm(p.fingers, p.palm);
        const glm::dquat q1 = p.endFingers ? orientationFromFingersPalm(*p.endFingers, *p.endPalm) : q0;
        // Where mirrored hands meet (resolve), the point that meets is the place's own.
        const bool meet = p.hands == HandRelation::Mirrored || p.hands == HandRelation::Symmetric;
        const auto meets = [&](const NotationPlace& place) { return meet && place.name.rfind("hand:", 0) == 0; };
        const auto touchAt = [&](const std::string& shape, const NotationPlace& place, const std::string& field) {
            return meets(place) ? point(shape, hand::Side::Right, place.name.substr(5), partPointer_ + field)
                                : point(shape, hand::Side::Right, p.touch, partPointer_ + "/touch");
        };
        const glm::dvec3 startTouch = touchAt(p.handshape, p.at, "/at");
        const glm::dvec3 endTouch = p.to ? touchAt(p.endHandshape, *p.to, "/path/to")
                                         : point(p.endHandshape, hand::Side::Right, p.touch, partPointer_ + "/touch");
        const glm::dvec3 start = palmOriginForTouch(resolve(p.at, partPointer_ + "/at"), q0, startTouch);
        glm::dvec3 end = start;
        // The base hand's own path (its palm origin's samples), when it has one.
        std::vector<Sample> baseStroke;
        if (!p.basePath.empty()) {
            const NotationPart& own = p.basePath.front();
            const glm::dvec3 from = basePose(static_cast<std::size_t>(part_))->positionMm;
            baseStroke = stroke(own, from, own.path == PathShape::Circle ? from : from + own.direction * own.sizeMm);
        }
        if (p.to) {
            if (!baseStroke.empty()) baseShiftMm_ = baseStroke.back().position - baseStroke.front().position;
            end = palmOriginForTouch(resolve(*p.to, partPointer_ + "/path/to"), q1, endTouch);
            baseShiftMm_ = glm::dvec3(0.0);
        }
        else if (p.path != PathShape::Circle && p.sizeMm > 0.0) end = start + p.direction * p.sizeMm;
        const std::vector<Sample> forth = stroke(p, start, end);
        // Time: n strokes and n − 1 returns.
        const int n = p.repeat;
        const double returnShare = p.returns == RepeatReturn::Lifted ? kLiftedReturnTime : p.returns == RepeatReturn::Continue ? 0.0 : 1.0;
        const double moving = p.seconds - p.holdSeconds;  // a hold at the end takes the rest
        const double ts = moving / (n + (n - 1) * returnShare), tr = ts * returnShare;
        CompiledNotation::Stroke record;
        record.part = part_;
        record.startSeconds = t0;
        record.endSeconds = t0 + p.seconds;
        record.strokeEndMm = forth.back().position;
        record.strokes = n;
        out_.parts.push_back(record);
        // The dominant hand's path, as (time, position, orientation blend u, shape, via).
        struct Key {
            double t;
            glm::dvec3 position;
            double u;
            bool via;
        };
        std::vector<Key> path;
        const auto addStroke = [&](double s0, bool junctionVia) {
            for (std::size_t k = 0; k < forth.size(); ++k) {
                if (k == 0 && !path.empty()) {
                    path.back().via = junctionVia;
                    continue;
                }
                path.push_back({s0 + forth[k].u * ts, forth[k].position, forth[k].u, forth[k].via});
            }
        };
        double now = t0;
        for (int r = 0; r < n; ++r) {
            addStroke(now, p.returns == RepeatReturn::Continue);
            for (const NotationContact& c : p.contacts) out_.contacts.push_back({now + c.when * ts, part_, 0, c.at, c.by, c.offsetMm});
            now += ts;
            if (r + 1 == n) break;
            if (p.returns == RepeatReturn::Retrace || p.returns == RepeatReturn::Trill) {
                for (std::size_t k = forth.size() - 1; k-- > 0;)
                    path.push_back({now + (1.0 - forth[k].u) * tr, forth[k].position, forth[k].u, forth[k].via});
            } else if (p.returns == RepeatReturn::Lifted) {
                // The return bulges the lift's way across the stroke; a tap whose lift is along
                // its own line goes straight back, quickly.
                const glm::dvec3 a = forth.back().position, b = forth.front().position;
                const glm::dvec3 along = glm::length(a - b) > 1e-6 ? glm::normalize(a - b) : glm::dvec3(0.0);
                const glm::dvec3 across = p.lift - glm::dot(p.lift, along) * along;
                if (glm::length(across) > 0.3) {
                    const double h = std::max(kLiftedMinimumMm, kLiftedHeight * glm::length(a - b));
                    path.push_back({now + 0.5 * tr, 0.5 * (a + b) + glm::normalize(across) * h, 0.5, true});
                }
                path.push_back({now + tr, b, 0.0, false});
            }
            now += tr;
        }
        // The hold: the hand stays where the last stroke ended until the part's end.
        if (p.holdSeconds > 0.0 && !path.empty()) path.push_back({t0 + p.seconds, path.back().position, path.back().u, false});
        // Local movement keys over a still hand (the parser allows oscillations only without a path).
        const bool oscillates = oscillatesLocally(p);
        if (oscillates && p.path == PathShape::None) {
            path.clear();
            // A repeated open-close ends in its end handshape, as one open-close does: 2n − 1 changes.
            const int steps = p.local == LocalMovement::OpenClose ? 2 * p.localCount - 1 : 2 * p.localCount;
            for (int k = 0; k <= steps; ++k) path.push_back({t0 + p.seconds * k / steps, start, static_cast<double>(k) / steps, false});
        }
        const HandRelation relation = p.hands;
        const bool hasBase = relation == HandRelation::Base || relation == HandRelation::Together;
        const std::optional<HandPose> base = hasBase ? basePose(static_cast<std::size_t>(part_)) : std::nullopt;
        const std::string baseShape = hasBase ? baseShapeFrom(static_cast<std::size_t>(part_)) : "";
        const glm::dquat startInverse = glm::inverse(q0);
        if (out_.hands.size() == 2 && relation == HandRelation::One) holds_.emplace_back(t0, t0 + p.seconds);
        for (std::size_t k = 0; k < path.size(); ++k) {
            const Key& key0 = path[k];
            for (int h = 0; h < static_cast<int>(out_.hands.size()); ++h) {
                if (h == 1 && relation == HandRelation::One) continue;  // holdLeftInOneHandedParts
                // Alternating: the left hand is half a cycle behind (the stroke's other end).
                const bool opposite = h == 1 && relation == HandRelation::Alternating;
                double u = key0.u;
                glm::dvec3 position = key0.position;
                if (opposite && !oscillates && p.path == PathShape::Circle) {
                    // Alternating circles: the left hand half a turn ahead on the mirrored circle,
                    // so in one plane the hands orbit each other (YEAR); it closes as the right does.
                    position = positionAt(forth, std::fmod(u + 0.5, 1.0));
                } else if (opposite && !oscillates) {
                    u = 1.0 - u;
                    position = positionAt(forth, u);
                }
                HandPose pose;
                pose.positionMm = position;
                pose.orientation = forearmTurn(q0, q1, u);
                std::string shape = handshapeAt(p, u);
                if (oscillates) applyLocal(p, k, opposite, start, pose, shape);
                if (h == 1) {
                    if (relation == HandRelation::Base) {
                        if (p.baseCarried) {
                            // Carried (HELP): the base hand moves with the dominant hand's path.
                            HandPose carried = *base;
                            carried.positionMm += position - start;
                            key(h, key0.t, carried, baseShape, key0.via);
                            continue;
                        }
                        // A still base hand, or one moving its own path in step with the strokes.
                        HandPose moved = *base;
                        if (!baseStroke.empty() && !oscillates) moved.positionMm = positionAt(baseStroke, key0.u);
                        key(h, key0.t, moved, baseShape, key0.via && !baseStroke.empty());
                        continue;
                    }
                    if (relation == HandRelation::Together) {
                        // One rigid unit: the left hand's start pose carried by the right hand's
                        // rotation and displacement from its own start.
                        const glm::dquat turn = pose.orientation * startInverse;
                        HandPose carried;
                        carried.orientation = turn * base->orientation;
                        carried.positionMm = pose.positionMm + turn * (base->positionMm - start);
                        key(h, key0.t, carried, baseShape, key0.via);
                        continue;
                    }
                    if (relation == HandRelation::Symmetric) {
                        // Parallel: the same displacement, from the mirrored start.
                        pose.positionMm = mirror(start) + (pose.positionMm - start);
                        pose.orientation = mirror(pose.orientation);
                    } else {
                        pose.positionMm = mirror(pose.positionMm);
                        pose.orientation = mirror(pose.orientation);
                    }
                    if (relation == HandRelation::Symmetric || relation == HandRelation::Mirrored)
                        pose.positionMm += glm::mix(p.leftOffsetMm, p.endLeftOffsetMm, u);
                }
                key(h, key0.t, pose, shape, key0.via);
            }
        }
    }

    // In a one-handed part of a two-handed sign the left hand holds still: where the previous
    // part left it, or (before any) where the next part starts it. Its keys are added at the
    // part's start and end, in time order.
    void holdLeftInOneHandedParts() {
        std::vector<VerbKeyframe>& keys = out_.keyframes[1];
        std::vector<bool>& flags = out_.passThrough[1];
        if (keys.empty()) return;  // no part moves it (cannot happen: twoHanded() says one does)
        for (const auto& [from, to] : holds_) {
            for (const double t : {from, to}) {
                const auto at = std::lower_bound(keys.begin(), keys.end(), t,
                                                 [](const VerbKeyframe& k, double v) { return k.timeSeconds < v - 1e-9; });
                if (at != keys.end() && std::abs(at->timeSeconds - t) <= 1e-9) continue;
                VerbKeyframe held = at == keys.begin() ? *at : *(at - 1);
                held.timeSeconds = t;
                const auto index = at - keys.begin();
                keys.insert(at, held);
                flags.insert(flags.begin() + index, false);
            }
        }
    }

    static glm::dvec3 positionAt(const std::vector<Sample>& s, double u) {
        for (std::size_t k = 0; k + 1 < s.size(); ++k)
            if (u <= s[k + 1].u + 1e-12) {
                const double w = s[k + 1].u > s[k].u ? (u - s[k].u) / (s[k + 1].u - s[k].u) : 0.0;
                return s[k].position + w * (s[k + 1].position - s[k].position);
            }
        return s.back().position;
    }

    // The handshape at u of a stroke: a flick snaps open early, other changes at the end.
    static std::string handshapeAt(const NotationPart& p, double u) {
        if (p.endHandshape == p.handshape) return p.handshape;
        if (p.local == LocalMovement::Flick) return u >= kFlickShare - 1e-9 ? p.endHandshape : p.handshape;
        return u >= 1.0 - 1e-9 ? p.endHandshape : p.handshape;
    }

    // The k-th key of an oscillating local movement: even keys at the start, odd keys at the
    // movement's other extreme (its opposite for the alternating left hand).
    static void applyLocal(const NotationPart& p, std::size_t k, bool opposite, const glm::dvec3& start, HandPose& pose,
                           std::string& shape) {
        const bool odd = (k % 2 == 1) != opposite;
        const double angle = p.localDegrees * kPi / 180.0;
        switch (p.local) {
            case LocalMovement::Wiggle: shape = odd ? p.localWith : p.handshape; break;
            case LocalMovement::OpenClose: shape = odd ? p.endHandshape : p.handshape; break;
            case LocalMovement::Twist:
                // About the fingers' axis, half the angle to each side of the described orientation.
                pose.orientation = glm::angleAxis((odd ? 0.5 : -0.5) * angle, fingersDirection(pose.orientation)) * pose.orientation;
                break;
            case LocalMovement::Nod: {
                // The wrist bends toward the palm and back.
                const glm::dvec3 axis = glm::normalize(glm::cross(fingersDirection(pose.orientation), palmDirection(pose.orientation)));
                if (odd) pose.orientation = glm::angleAxis(angle, axis) * pose.orientation;
                break;
            }
            case LocalMovement::Rub:
                pose.positionMm = start + (odd ? kRubMm : 0.0) * (p.direction == glm::dvec3(0.0) ? glm::dvec3(1, 0, 0) : p.direction);
                break;
            default: break;
        }
    }

    const SignNotation& n_;
    const std::map<std::string, glm::dvec3>& locations_;
    const HandshapeLibrary& shapes_;
    const hand::HandModel& model_;
    const JsonSource& source_;
    std::string pointer_, partPointer_;
    int part_ = 0;
    glm::dvec3 baseShiftMm_{0.0};  // where the base hand has moved on its own path (resolve)
    CompiledNotation out_;
    std::vector<std::pair<double, double>> holds_;  // one-handed parts of a two-handed sign
};

}  // namespace

const std::vector<std::string>& handPointNames() {
    static const std::vector<std::string> names{"base",   "palm",   "knuckles", "thumb-tip", "index-tip", "middle-tip",
                                                "ring-tip", "little-tip", "fingertips", "back", "heel", "radial",
                                                "ulnar",  "thumb",  "index",    "middle",    "ring",      "little",
                                                "finger-back", "finger-front", "wrist",  "wrist-front", "forearm",
                                                "forearm-front", "elbow", "elbow-front"};
    return names;
}

std::optional<glm::dvec3> handPointMm(const hand::HandModel& model, const hand::HandControls& controls, hand::Side side,
                                      const std::string& name) {
    if (std::optional<glm::dvec3> p = touchPointMm(model, controls, side, name)) return p;
    if (name == "finger-back" || name == "finger-front") {
        // The middle finger halfway along its length (knuckle to tip, along its three bones), on
        // its surface: the bone capsule's back or pad there. Follows the finger as it bends: a
        // flat hand's is the middle of the finger's back, a bent hand's the back of its bend, a
        // fist's the front of the fist over the middle joints (the chord's midpoint it was before
        // lay inside a fist and inside a C's curve, 20-30 mm from any surface).
        const hand::HandPose fk = hand::forwardKinematics(model, controls, hand::Side::Right);
        const int first = hand::firstBodyOf(hand::Digit::Middle);
        double along = 0.0;
        for (int b = 0; b < 3; ++b) along += hand::boneLengthMm(model, static_cast<hand::Body>(first + b));
        along *= 0.5;
        int b = 0;
        for (; b < 2; ++b) {
            const double length = hand::boneLengthMm(model, static_cast<hand::Body>(first + b));
            if (along <= length) break;
            along -= length;
        }
        const auto body = static_cast<hand::Body>(first + b);
        const hand::RigidTransform& bone = fk.bodies[static_cast<std::size_t>(body)];
        const glm::vec3 axis = hand::transformPoint(bone, {0.0f, 0.0f, static_cast<float>(along)});
        const glm::vec3 out = hand::transformPoint(bone, {name == "finger-front" ? 1.0f : -1.0f, 0.0f, static_cast<float>(along)}) - axis;
        // Out along the bone's back to the surface of the finger's capsules: past the bone's own
        // radius, and past the neighbouring bone's rounded end where it is wider. The pad stays
        // on its bone's surface: in a bent finger it is the crease, which no ray leaves.
        const std::array<hand::Capsule, hand::kBodyCount> capsules = hand::boneCapsules(model, fk);
        float reach = hand::boneRadiusMm(model, body);
        for (bool inside = name == "finger-back"; inside && reach < 30.0f;) {
            inside = false;
            for (int c = first; c < first + 3; ++c) {
                const hand::Capsule& capsule = capsules[static_cast<std::size_t>(c)];
                if (hand::distancePointSegment(axis + reach * out, capsule.start, capsule.end) < capsule.radiusMm - 1e-3f) inside = true;
            }
            if (inside) reach += 0.05f;
        }
        const glm::vec3 p = axis + reach * out;
        return glm::dvec3(side == hand::Side::Right ? p : hand::mirrorToLeft(p));
    }
    if (name == "radial") {
        // ASL-LEX 2.0's FingerRadial: the index finger's thumb side, halfway along its proximal
        // phalanx, on its surface (the bone's radius out from its line); follows the finger as it
        // bends (a fist's is the top of the fist, beside the knuckle). Not the palm's edge: there
        // the thumb of an A, L or S stands, and a hand put there goes through it.
        const hand::HandPose fk = hand::forwardKinematics(model, controls, hand::Side::Right);
        const hand::RigidTransform& bone = fk.bodies[static_cast<std::size_t>(hand::Body::IndexProximal)];
        const glm::vec3 p = hand::transformPoint(bone, {0.0f, hand::boneRadiusMm(model, hand::Body::IndexProximal),
                                                        0.5f * hand::boneLengthMm(model, hand::Body::IndexProximal)});
        return glm::dvec3(side == hand::Side::Right ? p : hand::mirrorToLeft(p));
    }
    static const std::vector<std::string> digits{"thumb", "index", "middle", "ring", "little"};
    for (std::size_t d = 0; d < digits.size(); ++d)
        if (name == digits[d]) return touchPointMm(model, controls, side, d == 0 ? "thumb-tip" : digits[d] + "-tip");
    const hand::HandDimensions& dim = model.dimensions;
    const float mid = 0.5f * hand::palmKnuckleZMm(model), heel = 0.15f * hand::palmKnuckleZMm(model);
    glm::vec3 p;
    if (name == "back") p = {2.0f * dim.palmCentreXMm - hand::palmarSurfaceXMm(model, mid), 0.0f, mid};
    else if (name == "heel") p = {hand::palmarSurfaceXMm(model, heel), 0.0f, heel};
    else if (name == "ulnar") p = {dim.palmCentreXMm, model.mcpPositionMm[3].y, mid};
    // [D] Along a straight forearm: the wrist's back 20 mm behind the palm frame's origin, the
    // middle of the forearm's back 120 mm, the elbow 260 mm (the default signer's forearm).
    else if (name == "wrist") p = {2.0f * dim.palmCentreXMm - hand::palmarSurfaceXMm(model, 0.0f), 0.0f, -20.0f};
    else if (name == "wrist-front") p = {hand::palmarSurfaceXMm(model, 0.0f), 0.0f, -20.0f};
    else if (name == "forearm") p = {-20.0f, 0.0f, -120.0f};
    // [D] The forearm's palm side and the crook of the elbow, 40 mm across from their backs.
    else if (name == "forearm-front") p = {20.0f, 0.0f, -120.0f};
    else if (name == "elbow") p = {-20.0f, 0.0f, -260.0f};
    else if (name == "elbow-front") p = {20.0f, 0.0f, -260.0f};
    else return std::nullopt;
    return glm::dvec3(side == hand::Side::Right ? p : hand::mirrorToLeft(p));
}

glm::dvec3 handPointInSpace(const HandPose& pose, const glm::dvec3& p) {
    // The palm frame's y appears as −y in signing space (lexicon.hpp, palmOriginForTouch).
    return pose.positionMm + pose.orientation * glm::dvec3(p.x, -p.y, p.z);
}

CompiledNotation compileSignNotation(const SignNotation& notation, const std::map<std::string, glm::dvec3>& locations,
                                     const HandshapeLibrary& shapes, const hand::HandModel& model, const JsonSource& source,
                                     const std::string& pointer) {
    return Compiler(notation, locations, shapes, model, source, pointer).compile();
}

}  // namespace signstim::stimuli
