// Checking a notation sign against the code it claims (sign_notation_check.hpp): the
// description's code against its ASL-LEX entry's, and the compiled motion — sampled as the
// signer samples a timeline (sampleTrack) — against the description.
#include "stimuli/story/sign_notation_check.hpp"

#include "stimuli/story/timeline.hpp"
#include "stimuli/verbs/sora.hpp"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace signstim::stimuli {
namespace {

// [D] Nearer than this to a place the hand is at it; up to kNearMm it is near it ("Away").
constexpr double kAtPlaceMm = 60.0, kNearMm = 150.0;
// [D] The check samples the motion at 240 Hz (8 samples a 30 fps frame).
constexpr double kSampleSeconds = 1.0 / 240.0;
// [D] The posed hands are sampled at 60 Hz (each sample is an arm solution, not a blend).
constexpr double kPosedSampleSeconds = 1.0 / 60.0;
// [D] A repetition returns to its stroke's end within 3 mm, having left it by 8 mm or more.
constexpr double kVisitMm = 3.0, kLeaveMm = 8.0;
// [D] The two hands of a two-handed sign that does not touch stay this far apart (palm centres).
constexpr double kHandsApartMm = 30.0;

std::string format(const char* f, double a, double b = 0.0) {
    char text[160];
    std::snprintf(text, sizeof text, f, a, b);
    return text;
}

// A hand's track as the timeline keeps it (times, poses, controls, pass-through keys).
std::vector<TimelineKey> trackOf(const LexiconSign& sign, std::size_t h, const HandshapeLibrary& shapes) {
    std::vector<TimelineKey> track;
    for (std::size_t k = 0; k < sign.keyframes[h].size(); ++k) {
        const VerbKeyframe& v = sign.keyframes[h][k];
        TimelineKey key;
        key.timeSeconds = v.timeSeconds;
        key.pose = v.pose;
        key.handshape = v.handshape;
        key.controls = shapes.at(v.handshape).controls;
        // As the timeline builder marks a sign's keys (coarticulation, timeline_builder.hpp):
        // every inner key passed through, the geometry deciding where the hand stops
        // (sampleTrack: a reversal or a hold stops it).
        key.passThrough = k > 0 && k + 1 < sign.keyframes[h].size();
        track.push_back(key);
    }
    return track;
}

struct Sampled {
    HandPose pose;
    hand::HandControls controls;
};

Sampled sampleAt(const std::vector<TimelineKey>& track, double t) {
    const TimelineSample s = sampleTrack(track, t);
    Sampled out;
    out.pose.positionMm = glm::mix(s.from->pose.positionMm, s.to->pose.positionMm, s.blend);
    out.pose.orientation = slerpShortest(s.from->pose.orientation, s.to->pose.orientation, s.blend);
    out.controls = hand::interpolate(s.from->controls, s.to->controls, static_cast<float>(s.blend));
    return out;
}

glm::dvec3 pointAt(const std::vector<TimelineKey>& track, double t, const std::string& name, hand::Side side,
                   const hand::HandModel& model) {
    const Sampled s = sampleAt(track, t);
    return handPointInSpace(s.pose, handPointMm(model, s.controls, side, name).value_or(glm::dvec3(0.0)));
}

std::string lower(std::string s) {
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// ASL-LEX writes the non-dominant hand's unmarked shapes in capitals ("B", "S"): B stands for
// any flat hand.
bool sameNondominant(const std::string& entry, const std::string& ours) {
    const std::string e = lower(entry);
    if (e == ours || entry == ours) return true;  // a handshape label, or "DominanceViolation"
    return e == "b" && (ours == "closed_b" || ours == "open_b" || ours == "flat_b");
}

std::string labelOf(const HandshapeLibrary& shapes, const std::string& name) {
    const Handshape* s = shapes.find(name);
    return s && !s->aslLexLabel.empty() ? s->aslLexLabel : "(" + name + ")";
}

// Battison's (1978) unmarked handshapes as ASL-LEX 2.0 labels them (its flat hands are B).
bool unmarkedHandshape(const std::string& label) {
    static const std::vector<std::string> unmarked{"open_b", "flat_b", "closed_b", "b", "a", "s", "c", "o", "1", "5"};
    return std::find(unmarked.begin(), unmarked.end(), label) != unmarked.end();
}

bool differs(const NotationProvenance& p, const std::string& field) {
    return std::find(p.differs.begin(), p.differs.end(), field) != p.differs.end();
}


// The arm's places (a point of handPointMm's straight forearm, in the palm frame: along -z from
// the wrist, x palmar) on a posed arm: along its own forearm, from the elbow to the wrist, with
// the palmar side the hand's palmar side turned square to it (the forearm carries the hand's
// pronation; the wrist flexes the hand, not the forearm, off its line).
HandPose posedForearm(const PosedHand& posed) {
    HandPose frame = posed.pose;
    const glm::dvec3 along = posed.pose.positionMm - posed.elbowMm;
    if (glm::length(along) < 1.0) return frame;
    const glm::dvec3 z = glm::normalize(along);
    const glm::dvec3 palmar = posed.pose.orientation * glm::dvec3(1, 0, 0);
    const glm::dvec3 x = palmar - glm::dot(palmar, z) * z;
    if (glm::length(x) < 1e-6) return frame;
    frame.orientation = orientationFromFingersPalm(z, glm::normalize(x));
    return frame;
}

// The checks on the posed hands (checkSignNotation with PosedHands): contact events at their
// moment, and each hand's turn from the notation's orientation.
void addPosedChecks(const LexiconSign& sign, const Lexicon& lexicon, const std::vector<std::vector<TimelineKey>>& tracks,
                    const hand::HandModel& model, const PosedHands& posed, std::vector<NotationCheck>& checks) {
    const auto sideOf = [&](std::size_t h) { return h == 0 ? hand::Side::Right : hand::Side::Left; };
    int index = 0;
    for (const ContactEvent& e : sign.contactEvents) {
        ++index;
        const std::string name = "posed contact " + std::to_string(index) + " " + e.by + " at " + e.at;
        const std::size_t h = static_cast<std::size_t>(e.hand);
        const std::optional<PosedHand> by = posed(sideOf(h), e.timeSeconds);
        std::optional<glm::dvec3> target;
        if (e.at.rfind("hand:", 0) == 0 || e.at.rfind("arm:", 0) == 0) {
            const std::optional<PosedHand> other = tracks.size() < 2 ? std::nullopt : posed(hand::Side::Left, e.timeSeconds);
            if (other) {
                const bool arm = e.at.rfind("arm:", 0) == 0;
                const std::string point = e.at.substr(e.at.find(':') + 1);
                target = handPointInSpace(arm ? posedForearm(*other) : other->pose,
                                          handPointMm(model, sampleAt(tracks.back(), e.timeSeconds).controls, hand::Side::Left, point)
                                              .value_or(glm::dvec3(0.0)));
            }
        } else if (const auto found = lexicon.locations.find(e.at); found != lexicon.locations.end()) {
            target = found->second;
        }
        if (!by || !target) {
            checks.push_back({name, false, "no posed hand or place"});
            continue;
        }
        *target += e.offsetMm;
        const glm::dvec3 point = handPointInSpace(
            by->pose, handPointMm(model, sampleAt(tracks[h], e.timeSeconds).controls, sideOf(h), e.by).value_or(glm::dvec3(0.0)));
        const double gap = glm::distance(*target, point);
        checks.push_back({name, gap <= kContactReachedMm, format("%.1f mm at ", gap) + format("%.3f s", e.timeSeconds)});
    }
    // Each hand's posed orientation against the one its motion asks, every sample of the sign's
    // keys (the motion's own: between two keys half a turn apart the notation's interpolation is
    // ambiguous, and the signer's is the one seen).
    const double total = sign.durationSeconds();
    for (std::size_t h = 0; h < tracks.size(); ++h) {
        double worst = 0.0, when = 0.0;
        for (double t = 0.0; t <= total + 1e-9; t += kPosedSampleSeconds) {
            const std::optional<PosedHand> p = posed(sideOf(h), t);
            if (!p) continue;
            const double deg = p->orientationErrorDeg;
            if (deg > worst) worst = deg, when = t;
        }
        checks.push_back({std::string("posed orientation, ") + (h == 0 ? "right" : "left") + " hand", worst <= kPosedOrientationDeg,
                          format("%.0f degrees from the asked orientation at worst, ", worst) + format("at %.3f s", when) +
                              format(" (at most %.0f)", kPosedOrientationDeg)});
    }
}

}  // namespace

std::pair<std::string, std::string> aslLexLocation(const std::string& place, double distanceMm) {
    static const std::vector<std::tuple<std::string, std::string, std::string>> table{
        // name prefix, major, minor (ASL-LEX 2.0's MajorLocation/MinorLocation values)
        {"neutral", "Neutral", "Neutral"},     {"head-top", "Head", "HeadTop"},   {"forehead", "Head", "Forehead"},
        {"temple", "Head", "Forehead"},        {"eye", "Head", "Eye"},            {"nose", "Head", "CheekNose"},
        {"cheek", "Head", "CheekNose"},        {"ear", "Head", "CheekNose"},      {"upper-lip", "Head", "UpperLip"},
        {"mouth", "Head", "Mouth"},            {"under-chin", "Head", "UnderChin"}, {"chin", "Head", "Chin"},
        {"neck", "Body", "Neck"},              {"shoulder", "Body", "Shoulder"},  {"a-shoulder", "Body", "Shoulder"},
        {"clavicle", "Body", "Clavicle"},      {"chest", "Body", "TorsoTop"},     {"torso", "Body", "TorsoMid"},
        {"waist", "Body", "Waist"},            {"hips", "Body", "Hips"},          {"a-thigh", "Body", "Hips"},
        {"upper-arm", "Arm", "UpperArm"},      {"hand:palm", "Hand", "Palm"},     {"hand:back", "Hand", "PalmBack"},
        {"hand:heel", "Hand", "Heel"},         {"hand:radial", "Hand", "FingerRadial"}, {"hand:ulnar", "Hand", "FingerUlnar"},
        {"hand:finger-back", "Hand", "FingerBack"}, {"hand:finger-front", "Hand", "FingerFront"},
        {"hand:", "Hand", "FingerTip"},        {"arm:wrist-front", "Arm", "WristFront"}, {"arm:wrist", "Arm", "WristBack"},
        {"arm:forearm-front", "Arm", "ForearmFront"}, {"arm:forearm", "Arm", "ForearmBack"},
        // ASL-LEX 2.0 has no ElbowFront: it codes the elbow as ElbowBack, front or back.
        {"arm:elbow", "Arm", "ElbowBack"}};
    for (const auto& [prefix, major, minor] : table) {
        if (place.rfind(prefix, 0) != 0) continue;
        if (major == "Neutral" || distanceMm > kNearMm) return {"Neutral", "Neutral"};
        if (distanceMm > kAtPlaceMm) return {major, major + "Away"};
        return {major, minor};
    }
    return {"Other", "Other"};
}

std::vector<AslLexCode> deriveAslLexCode(const SignNotation& n, const HandshapeLibrary& shapes) {
    std::vector<AslLexCode> codes;
    for (const NotationPart& p : n.parts) {
        AslLexCode c;
        c.handshape = labelOf(shapes, p.handshape);
        const bool base = p.hands == HandRelation::Base && !p.baseHandshape.empty();
        const bool sameShape = base && labelOf(shapes, p.baseHandshape) == c.handshape;
        if (p.hands == HandRelation::One || (p.hands == HandRelation::Base && !base)) c.signType = "OneHanded";
        else if (!base) c.signType = "SymmetricalOrAlternating";
        // Both hands move (together, or a base hand with its own path): Battison's (1978)
        // symmetry condition, which a different handshape violates (ASL-LEX: DominanceViolation).
        else if (p.bothHandsMove()) c.signType = sameShape ? "SymmetricalOrAlternating" : "DominanceViolation";
        // A still base hand in the dominant's own marked handshape (not one of Battison's 1978
        // unmarked B, A, S, C, O, 1, 5): ASL-LEX 2.0 codes it DominanceViolation (NAME, CHAIR:
        // 60 of its 63 DominanceViolation signs have a marked handshape; 6 of its 162
        // AsymmetricalSameHandshape signs do). Only in a sign's first part: its coding of later
        // morphemes never uses the type (15 such second parts, SISTER, FUN, are Asymmetrical).
        else if (sameShape && !unmarkedHandshape(c.handshape) && codes.empty()) c.signType = "DominanceViolation";
        else c.signType = sameShape ? "AsymmetricalSameHandshape" : "AsymmetricalDifferentHandshape";
        if (base && c.signType == "DominanceViolation") c.nondominant = "DominanceViolation";
        else if (base) c.nondominant = labelOf(shapes, p.baseHandshape);
        else if (p.hands != HandRelation::One && p.hands != HandRelation::Base) c.nondominant = c.handshape;
        switch (p.path) {
            case PathShape::None: c.movement = "None"; break;
            case PathShape::Straight: c.movement = "Straight"; break;
            case PathShape::Arc:
            case PathShape::Wavy: c.movement = "Curved"; break;
            case PathShape::Circle: c.movement = "Circular"; break;
            case PathShape::Zigzag: c.movement = "Z-shaped"; break;
        }
        c.repeated = p.repeat > 1 || (oscillatesLocally(p) && p.localCount > 1) ? 1 : 0;
        // ASL-LEX codes where the hand is at onset; a sign that touches, where it touches.
        // Hands that touch each other without a base hand (MORE, FAMILY) touch in neutral
        // space, as ASL-LEX codes them.
        // So do two moving hands that touch (no hand is the other's still base).
        const std::string& first = p.contacts.empty() ? std::string() : p.contacts.front().at;
        const bool onOther = first.rfind("hand:", 0) == 0 || first.rfind("arm:", 0) == 0;
        const bool handsMeet = onOther && (p.bothHandsMove() || (p.hands != HandRelation::Base && first.rfind("hand:", 0) == 0));
        const auto [major, minor] = handsMeet         ? std::pair<std::string, std::string>{"Neutral", "Neutral"}
                                    : p.contacts.empty() ? aslLexLocation(p.at.name, glm::length(p.at.offsetMm))
                                                         : aslLexLocation(p.contacts.front().at, glm::length(p.contacts.front().offsetMm));
        c.majorLocation = major;
        c.minorLocation = minor;
        c.contact = p.contacts.empty() ? 0 : 1;
        codes.push_back(c);
    }
    return codes;
}

std::string describeAslLexCode(const AslLexCode& c) {
    std::string s = "handshape " + c.handshape + ", " + c.signType;
    if (!c.nondominant.empty()) s += " (other hand " + c.nondominant + ")";
    s += ", movement " + c.movement + ", " + c.majorLocation + "/" + c.minorLocation;
    s += c.contact == 1 ? ", contact" : c.contact == 0 ? ", no contact" : "";
    s += c.repeated == 1 ? ", repeated" : c.repeated == 0 ? ", once" : "";
    return s;
}

std::vector<NotationCheck> checkSignNotation(const LexiconSign& sign, const Lexicon& lexicon, const HandshapeLibrary& shapes,
                                             const hand::HandModel& model, const PosedHands& posed) {
    std::vector<NotationCheck> checks;
    if (!sign.notation) return checks;
    const SignNotation& n = *sign.notation;
    const NotationProvenance& prov = n.provenance;
    const std::vector<AslLexCode> derived = deriveAslLexCode(n, shapes);
    const auto add = [&](std::string name, bool ok, std::string detail) { checks.push_back({std::move(name), ok, std::move(detail)}); };

    // The description's code against the entry's (where the variant does not say it differs).
    for (std::size_t i = 0; i < prov.code.size() && i < derived.size(); ++i) {
        const AslLexCode &e = prov.code[i], &d = derived[i];
        std::string wrong;
        const auto compare = [&](const char* field, const std::string& entry, const std::string& ours, bool same) {
            if (!entry.empty() && !same && !differs(prov, field)) wrong += std::string(wrong.empty() ? "" : "; ") + field + " " + ours + " (entry: " + entry + ")";
        };
        compare("handshape", e.handshape, d.handshape, e.handshape == d.handshape);
        compare("signType", e.signType, d.signType, e.signType == d.signType);
        compare("movement", e.movement, d.movement, e.movement == d.movement);
        compare("major", e.majorLocation, d.majorLocation, e.majorLocation == d.majorLocation);
        compare("minor", e.minorLocation, d.minorLocation, e.minorLocation == d.minorLocation);
        compare("nondominant", e.nondominant, d.nondominant.empty() ? "none" : d.nondominant, sameNondominant(e.nondominant, d.nondominant));
        if (e.repeated >= 0) compare("repeated", std::to_string(e.repeated), std::to_string(d.repeated), e.repeated == d.repeated);
        if (e.contact >= 0) compare("contact", std::to_string(e.contact), std::to_string(d.contact), e.contact == d.contact);
        add("code, part " + std::to_string(i + 1), wrong.empty(), wrong.empty() ? describeAslLexCode(d) : wrong);
    }
    if (prov.durationMs > 0.0 && !differs(prov, "duration")) {
        const double ratio = sign.durationSeconds() * 1000.0 / prov.durationMs;
        add("duration", std::abs(ratio - 1.0) <= kDurationTolerance + 1e-9,
            format("%.0f ms, ", sign.durationSeconds() * 1000.0) + format("%.2f of ASL-LEX's SignDuration", ratio));
    }

    std::vector<std::vector<TimelineKey>> tracks;
    for (std::size_t h = 0; h < sign.keyframes.size(); ++h) tracks.push_back(trackOf(sign, h, shapes));
    const std::vector<TimelineKey>& right = tracks.front();
    const double total = sign.durationSeconds();
    const auto otherHandPoint = [&](double t, const std::string& place) {
        return pointAt(tracks.back(), t, place.substr(place.find(':') + 1), hand::Side::Left, model);
    };
    const auto placePoint = [&](double t, const std::string& place) -> std::optional<glm::dvec3> {
        if (place.rfind("hand:", 0) == 0 || place.rfind("arm:", 0) == 0) {
            if (tracks.size() < 2) return std::nullopt;
            return otherHandPoint(t, place);
        }
        const auto found = lexicon.locations.find(place);
        if (found == lexicon.locations.end()) return std::nullopt;
        return found->second;
    };

    for (std::size_t i = 0; i < n.parts.size() && i < sign.strokes.size(); ++i) {
        const NotationPart& p = n.parts[i];
        const CompiledNotation::Stroke& s = sign.strokes[i];
        const std::string part = n.parts.size() > 1 ? ", part " + std::to_string(i + 1) : "";
        // Handshape at the hold (the part's first key).
        const TimelineSample at = sampleTrack(right, s.startSeconds);
        const std::string label = labelOf(shapes, at.blend < 0.5 ? at.from->handshape : at.to->handshape);
        add("handshape at the hold" + part, label == derived[i].handshape, label);
        // The nearest place to the touching point at the part's start (at its first contact).
        double placeTime = s.startSeconds;
        std::string touchName = p.touch;
        for (const ContactEvent& e : sign.contactEvents)
            if (e.part == static_cast<int>(i)) {
                placeTime = e.timeSeconds, touchName = e.by;
                break;
            }
        const glm::dvec3 touch = pointAt(right, placeTime, touchName, hand::Side::Right, model);
        std::string nearest;
        double best = 1e18;
        for (const auto& [name, point] : lexicon.locations)
            if (glm::distance(point, touch) < best) best = glm::distance(point, touch), nearest = name;
        if (p.hands == HandRelation::Base && !p.baseHandshape.empty() && !p.bothHandsMove())
            for (const char* name : {"hand:palm", "hand:back", "hand:heel", "hand:radial", "hand:ulnar", "hand:fingertips",
                                     "hand:thumb", "hand:index", "hand:middle", "hand:ring", "hand:little",
                                     "hand:finger-back", "hand:finger-front", "arm:wrist", "arm:wrist-front", "arm:forearm",
                                     "arm:forearm-front", "arm:elbow", "arm:elbow-front"}) {
                const double d = glm::distance(otherHandPoint(placeTime, name), touch);
                if (d < best) best = d, nearest = name;
            }
        const auto [major, minor] = aslLexLocation(nearest, best);
        add("place" + part, major == derived[i].majorLocation && minor == derived[i].minorLocation,
            major + "/" + minor + " (nearest: " + nearest + format(", %.0f mm)", best));
        // Repetitions: returns to the first stroke's end.
        const bool oscillates = oscillatesLocally(p) && p.path == PathShape::None;
        int visits = 0;
        // A circle's stroke ends where it starts: the hand must leave it first.
        bool armed = p.path != PathShape::Circle;
        double peak = 0.0;
        std::vector<double> signal;
        const Sampled first = sampleAt(right, s.startSeconds);
        for (double t = s.startSeconds; t <= s.endSeconds + 1e-9; t += kSampleSeconds) {
            const Sampled now = sampleAt(right, std::min(t, s.endSeconds));
            if (!oscillates) {
                const double d = glm::distance(now.pose.positionMm, s.strokeEndMm);
                if (d > kLeaveMm) armed = true;
                if (d < kVisitMm && armed) ++visits, armed = false;
            } else {
                // How far the hand is from its start in the local movement's own measure.
                double m = 0.0;
                for (std::size_t f = 0; f < 4; ++f)
                    m += std::abs(now.controls.fingers[f].bend - first.controls.fingers[f].bend) +
                         std::abs(now.controls.fingers[f].hook - first.controls.fingers[f].hook);
                m += glm::distance(now.pose.positionMm, first.pose.positionMm) / 10.0;
                m += 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(now.pose.orientation, first.pose.orientation))));
                signal.push_back(m);
                peak = std::max(peak, m);
            }
        }
        int strokes = visits;
        if (oscillates) {
            strokes = 0;
            bool high = false;
            for (double m : signal) {
                if (!high && m > 0.6 * peak) ++strokes, high = true;
                if (high && m < 0.3 * peak) high = false;
            }
        }
        const int expected = oscillates ? p.localCount : p.repeat;
        add("repetitions" + part, strokes == expected, format("%.0f (", strokes) + format("described: %.0f)", expected));
        if (p.path == PathShape::Circle) {
            const double gap = glm::distance(sampleAt(right, s.endSeconds).pose.positionMm, first.pose.positionMm);
            add("circle closes" + part, gap < 0.5, format("%.2f mm from its start at the end", gap));
        }
        // Via points are passed, not stopped at.
        double slowest = 1e18;
        int vias = 0;
        for (std::size_t k = 0; k < right.size(); ++k) {
            if (sign.passThrough.empty() || !sign.passThrough[0][k] || right[k].timeSeconds < s.startSeconds || right[k].timeSeconds > s.endSeconds) continue;
            const double t = right[k].timeSeconds, dt = 1e-3;
            const double speed = glm::distance(sampleAt(right, t + dt).pose.positionMm, sampleAt(right, t - dt).pose.positionMm) / (2.0 * dt);
            slowest = std::min(slowest, speed);
            ++vias;
        }
        if (vias > 0) add("via points passed" + part, slowest > 1.0, format("%.0f via points, slowest %.0f mm/s", vias, slowest));
    }

    // Contact events: reached within 10 mm at their moment; apart between them.
    int index = 0;
    for (const ContactEvent& e : sign.contactEvents) {
        ++index;
        std::optional<glm::dvec3> target = placePoint(e.timeSeconds, e.at);
        if (target) *target += e.offsetMm;
        const glm::dvec3 by = pointAt(tracks[static_cast<std::size_t>(e.hand)], e.timeSeconds, e.by, hand::Side::Right, model);
        const std::string name = "contact " + std::to_string(index) + " " + e.by + " at " + e.at;
        if (!target) {
            add(name, false, "no such place");
            continue;
        }
        const double gap = glm::distance(*target, by);
        add(name, gap <= kContactReachedMm, format("%.1f mm at ", gap) + format("%.3f s", e.timeSeconds));
    }
    for (std::size_t k = 0; k + 1 < sign.contactEvents.size(); ++k) {
        const ContactEvent &a = sign.contactEvents[k], &b = sign.contactEvents[k + 1];
        if (a.at != b.at || a.by != b.by || a.part != b.part || b.timeSeconds - a.timeSeconds < 1e-3) continue;
        // Hands moving together keep their touch (BABY's arms rest on each other as they rock).
        if (n.parts[static_cast<std::size_t>(a.part)].hands == HandRelation::Together) continue;
        const double t = 0.5 * (a.timeSeconds + b.timeSeconds);
        std::optional<glm::dvec3> target = placePoint(t, a.at);
        if (!target) continue;
        *target += a.offsetMm;
        const double gap = glm::distance(*target, pointAt(right, t, a.by, hand::Side::Right, model));
        add("apart between contacts " + std::to_string(k + 1) + " and " + std::to_string(k + 2), gap >= kApartMm,
            format("%.1f mm at ", gap) + format("%.3f s", t));
    }
    // Two hands that never touch stay apart; the relation holds at every sample.
    if (tracks.size() == 2) {
        // The relation holds inside its own parts' strokes (a compound changes it).
        bool anyMirrored = false, anyBase = false, anyTogether = false;
        for (const NotationPart& p : n.parts) {
            anyMirrored = anyMirrored || p.hands == HandRelation::Mirrored;
            anyBase = anyBase || (p.hands == HandRelation::Base && !p.bothHandsMove());
            anyTogether = anyTogether || p.hands == HandRelation::Together;
        }
        // A part entered from another relation: the hands arrive from places that are no mirror
        // images, and the pass through the part's first key carries that in (sampleTrack), so
        // the relation is measured from its second key on.
        // The mirrored part at t, if any (its left hand offset from the mirror image by leftOffset).
        const auto mirroredAt = [&](double t) -> const NotationPart* {
            for (std::size_t i = 0; i < n.parts.size() && i < sign.strokes.size(); ++i) {
                if (n.parts[i].hands != HandRelation::Mirrored || t < sign.strokes[i].startSeconds - 1e-9 ||
                    t > sign.strokes[i].endSeconds + 1e-9)
                    continue;
                if (i == 0 || n.parts[i - 1].hands == HandRelation::Mirrored) return &n.parts[i];
                for (const TimelineKey& key : tracks[0])
                    if (key.timeSeconds > sign.strokes[i].startSeconds + 1e-9) return t >= key.timeSeconds - 1e-9 ? &n.parts[i] : nullptr;
            }
            return nullptr;
        };
        double closest = 1e18, worst = 0.0, worstMoving = 0.0;
        for (double t = 0.0; t <= total + 1e-9; t += kSampleSeconds) {
            const Sampled r = sampleAt(tracks[0], t), l = sampleAt(tracks[1], t);
            const glm::dvec3 rp = handPointInSpace(r.pose, *handPointMm(model, r.controls, hand::Side::Right, "palm"));
            const glm::dvec3 lp = handPointInSpace(l.pose, *handPointMm(model, l.controls, hand::Side::Left, "palm"));
            closest = std::min(closest, glm::distance(rp, lp));
            if (const NotationPart* mirrored = mirroredAt(t)) {
                // The left hand's offset from the mirror image lies on the line from the part's
                // start offset to its end offset (leftOffset, endLeftOffset; the point itself when
                // the offset is held). Where it changes, the two hands' keys passed through are
                // joined by curves fitted to each hand's own keys (sampleTrack), which part by up
                // to about 1 mm between keys (CHANGE: 0.6 mm for an 80 mm exchange).
                const glm::dvec3 off = l.pose.positionMm - glm::dvec3(-r.pose.positionMm.x, r.pose.positionMm.y, r.pose.positionMm.z);
                const glm::dvec3 a = mirrored->leftOffsetMm, along = mirrored->endLeftOffsetMm - a;
                const bool changes = glm::dot(along, along) > 0.0;
                const double u = changes ? glm::dot(off - a, along) / glm::dot(along, along) : 0.0;
                double& w = changes ? worstMoving : worst;
                w = std::max(w, glm::distance(off, a + u * along));
            }
        }
        if (!sign.contact.hands) add("hands apart", closest >= kHandsApartMm, format("palms at least %.0f mm apart", closest));
        if (anyMirrored)
            add("hands mirrored", worst < 0.5 && worstMoving < 1.0,
                format("%.2f mm from the mirror image at worst", worst) +
                    (worstMoving > 0.0 ? format(", %.2f mm where the left hand's offset changes (at most 1)", worstMoving) : std::string()));
        if (anyBase) {
            // A still base hand holds its place; a carried one (HELP) keeps its place relative to
            // the dominant hand (its offset varies by < 0.5 mm); one with its own path is not still.
            double moved = 0.0, drift = 0.0;
            bool still = false, carried = false;
            for (std::size_t i = 0; i < sign.strokes.size(); ++i) {
                if (n.parts[i].baseHandshape.empty() || n.parts[i].bothHandsMove()) continue;
                const double t0 = sign.strokes[i].startSeconds;
                const glm::dvec3 offset0 = sampleAt(tracks[1], t0).pose.positionMm - sampleAt(tracks[0], t0).pose.positionMm;
                for (double t = t0; t <= sign.strokes[i].endSeconds; t += kSampleSeconds) {
                    const glm::dvec3 left = sampleAt(tracks[1], t).pose.positionMm;
                    if (n.parts[i].baseCarried)
                        drift = std::max(drift, glm::distance(left - sampleAt(tracks[0], t).pose.positionMm, offset0));
                    else
                        moved = std::max(moved, glm::distance(left, sampleAt(tracks[1], t0).pose.positionMm));
                }
                (n.parts[i].baseCarried ? carried : still) = true;
            }
            if (still || !carried) add("base hand still", moved < 0.5, format("moves %.2f mm", moved));
            if (carried) add("base hand carried", drift < 0.5, format("%.2f mm from its place by the dominant hand at worst", drift));
        }
        if (anyTogether) {
            // One rigid unit: the left palm centre and fingertips keep their place in the right
            // hand's frame (as sampled, between keys too).
            double drift = 0.0;
            for (std::size_t i = 0; i < sign.strokes.size(); ++i) {
                if (n.parts[i].hands != HandRelation::Together) continue;
                const auto relative = [&](double t, const char* point) {
                    const Sampled r = sampleAt(tracks[0], t), l = sampleAt(tracks[1], t);
                    const glm::dvec3 at = handPointInSpace(l.pose, *handPointMm(model, l.controls, hand::Side::Left, point));
                    return glm::inverse(r.pose.orientation) * (at - r.pose.positionMm);
                };
                for (double t = sign.strokes[i].startSeconds; t <= sign.strokes[i].endSeconds; t += kSampleSeconds)
                    for (const char* point : {"palm", "fingertips"})
                        drift = std::max(drift, glm::distance(relative(t, point), relative(sign.strokes[i].startSeconds, point)));
            }
            add("hands rigid", drift < 0.5, format("the left hand moves %.2f mm in the right hand's frame at worst", drift));
        }
    }
    if (posed) addPosedChecks(sign, lexicon, tracks, model, posed, checks);
    std::string relations;
    for (const NotationPart& p : n.parts) relations += (relations.empty() ? "" : ", ") + toString(p.hands);
    add("hands", static_cast<int>(sign.hands.size()) == (n.twoHanded() ? 2 : 1), std::to_string(sign.hands.size()) + " (" + relations + ")");
    return checks;
}

}  // namespace signstim::stimuli
