// Reading a sign's "notation" object (docs/lexicon.md): every field checked, every mistake
// named at its file, line and field.
#include "stimuli/story/sign_notation.hpp"

#include <algorithm>
#include <cmath>
#include <set>

namespace signstim::stimuli {
namespace {

using nlohmann::json;

// [D] A part of a citation form lasts well under 3 s; a path, circle or offset over 600 mm
// leaves the signing space (SPEC §3.1: the signing space is ~1 m wide).
constexpr NumberRange kPartSeconds{0.05, 3.0, "s"};
constexpr NumberRange kTransitionSeconds{0.0, 1.0, "s"};
constexpr NumberRange kSizeMm{0.0, 600.0, "mm"};
constexpr NumberRange kOffsetMm{-600.0, 600.0, "mm"};
constexpr NumberRange kDegrees{0.0, 180.0, "degrees"};
constexpr NumberRange kDurationMs{50.0, 5000.0, "ms"};

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

class NotationReader {
public:
    NotationReader(const JsonSource& source, const HandshapeLibrary& shapes) : source_(source), shapes_(shapes) {}

    SignNotation read(const std::string& signPointer) {
        const std::string p = signPointer + "/notation";
        const json& n = at(p);
        if (!n.is_object()) fail(p, "expected {\"hands\": ..., \"parts\": [...], \"aslLex\": {...}}");
        only(n, p, {"hands", "parts", "aslLex", "about"});
        SignNotation out;
        out.hands = relation(n, p, HandRelation::One);
        if (!n.contains("parts") || !n["parts"].is_array() || n["parts"].empty() || n["parts"].size() > 4)
            fail(p + "/parts", "expected 1 to 4 parts (a compound has one per sign it joins)");
        for (std::size_t i = 0; i < n["parts"].size(); ++i)
            out.parts.push_back(readPart(n["parts"][i], p + "/parts/" + std::to_string(i), out.hands, i == 0));
        if (n.contains("aslLex")) out.provenance = readProvenance(n["aslLex"], p + "/aslLex", out.parts.size());
        return out;
    }

private:
    HandRelation relation(const json& object, const std::string& p, HandRelation fallback) const {
        if (!object.contains("hands")) return fallback;
        static const std::map<std::string, HandRelation> relations{{"one", HandRelation::One},
                                                                   {"symmetric", HandRelation::Symmetric},
                                                                   {"mirrored", HandRelation::Mirrored},
                                                                   {"alternating", HandRelation::Alternating},
                                                                   {"base", HandRelation::Base},
                                                                   {"together", HandRelation::Together}};
        return choose(relations, text(object, p, "hands", ""), p + "/hands");
    }

    const json& at(const std::string& pointer) const { return source_.root.at(json::json_pointer(pointer)); }
    [[noreturn]] void fail(const std::string& pointer, const std::string& message) const { source_.failAt(pointer, message); }

    void only(const json& object, const std::string& p, const std::vector<std::string>& known) const {
        for (const auto& item : object.items())
            if (std::find(known.begin(), known.end(), item.key()) == known.end())
                fail(p + "/" + jsonPointerToken(item.key()), "unknown field '" + item.key() + "' (known: " + joined(known) + ")");
    }

    template <class T>
    T choose(const std::map<std::string, T>& options, const std::string& value, const std::string& p) const {
        const auto found = options.find(value);
        if (found != options.end()) return found->second;
        std::vector<std::string> names;
        for (const auto& option : options) names.push_back(option.first);
        fail(p, "'" + value + "' is not one of " + joined(names));
    }

    std::string text(const json& object, const std::string& p, const std::string& key, const std::string& fallback) const {
        if (!object.contains(key)) return fallback;
        if (!object[key].is_string()) fail(p + "/" + key, "expected a text");
        return object[key].get<std::string>();
    }

    double number(const json& object, const std::string& p, const std::string& key, const NumberRange& range,
                  double fallback) const {
        if (!object.contains(key)) return fallback;
        return source_.number(object[key], p + "/" + key, range);
    }

    int whole(const json& object, const std::string& p, const std::string& key, int lo, int hi, int fallback) const {
        if (!object.contains(key)) return fallback;
        const json& v = object[key];
        if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
            fail(p + "/" + key, "expected a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
        return v.get<int>();
    }

    glm::dvec3 vector3(const json& value, const std::string& p, const NumberRange& range) const {
        if (!value.is_array() || value.size() != 3) fail(p, "expected [x, y, z]");
        glm::dvec3 v;
        for (int i = 0; i < 3; ++i) v[i] = source_.number(value[static_cast<std::size_t>(i)], p + "/" + std::to_string(i), range);
        return v;
    }

    // A direction: words joined by '-' ("forward-down": up, down, left, right, forward, back;
    // the signer's left and right) or [x, y, z]; returned as a unit vector.
    glm::dvec3 direction(const json& value, const std::string& p) const {
        glm::dvec3 d(0.0);
        if (value.is_string()) {
            static const std::map<std::string, glm::dvec3> words{{"up", {0, 1, 0}},      {"down", {0, -1, 0}},
                                                                 {"left", {-1, 0, 0}},   {"right", {1, 0, 0}},
                                                                 {"forward", {0, 0, 1}}, {"back", {0, 0, -1}}};
            const std::string s = value.get<std::string>();
            std::size_t start = 0;
            while (start <= s.size()) {
                const std::size_t dash = std::min(s.find('-', start), s.size());
                d += choose(words, s.substr(start, dash - start), p);
                start = dash + 1;
            }
        } else {
            d = vector3(value, p, NumberRange{-1.0, 1.0, ""});
        }
        if (glm::length(d) < 1e-6) fail(p, "the direction has no length");
        return glm::normalize(d);
    }

    NotationPlace place(const json& object, const std::string& p, const std::string& key, const std::string& offsetKey) const {
        NotationPlace out;
        if (!object.contains(key) || !object[key].is_string() || object[key].get<std::string>().empty())
            fail(p + "/" + key, "expected a place: a body location (\"chin\"), \"hand:palm\" ... or \"neutral\"");
        out.name = object[key].get<std::string>();
        if (object.contains(offsetKey)) {
            out.offsetMm = vector3(object[offsetKey], p + "/" + offsetKey, kOffsetMm);
            if (glm::length(out.offsetMm) > 400.0) fail(p + "/" + offsetKey, "an offset from a place is at most 400 mm");
        }
        return out;
    }

    std::string shape(const json& object, const std::string& p, const std::string& key, bool required,
                      const std::string& fallback = "") const {
        if (!object.contains(key)) {
            if (required) fail(p + "/" + key, "name the handshape (one of " + shapes_.file + ")");
            return fallback;
        }
        const std::string name = text(object, p, key, "");
        if (!shapes_.find(name)) fail(p + "/" + key, "unknown handshape '" + name + "' (not in " + shapes_.file + ")");
        return name;
    }

    void orientation(const json& object, const std::string& p, const std::string& fingersKey, const std::string& palmKey,
                     glm::dvec3& fingers, glm::dvec3& palm, bool required) const {
        const bool hasF = object.contains(fingersKey), hasP = object.contains(palmKey);
        if (!hasF && !hasP && !required) return;
        if (!hasF || !hasP) fail(p + "/" + (hasF ? palmKey : fingersKey), "give \"" + fingersKey + "\" and \"" + palmKey + "\" together");
        fingers = direction(object[fingersKey], p + "/" + fingersKey);
        palm = direction(object[palmKey], p + "/" + palmKey);
        if (std::abs(glm::dot(fingers, palm)) > 0.9)
            fail(p + "/" + palmKey, "the palm cannot face where the fingers point (they are nearly parallel)");
    }

    NotationPart readPart(const json& part, const std::string& p, HandRelation signRelation, bool first) {
        if (!part.is_object()) fail(p, "a part is an object {\"seconds\": ..., \"handshape\": ..., \"at\": ...}");
        only(part, p, {"hands", "seconds", "transition", "handshape", "endHandshape", "fingers", "palm", "endFingers", "endPalm", "at",
                       "offset", "touch", "path", "local", "repeat", "base", "contact", "clasp", "about", "leftOffset", "endLeftOffset", "hold"});
        NotationPart out;
        out.line = source_.lineAt(p);
        out.hands = relation(part, p, signRelation);
        const HandRelation relation = out.hands;
        if (!part.contains("seconds")) fail(p + "/seconds", "give the part's citation time in seconds");
        out.seconds = number(part, p, "seconds", kPartSeconds, 0.0);
        out.transitionSeconds = number(part, p, "transition", kTransitionSeconds, first ? 0.0 : 0.15);
        if (first && out.transitionSeconds > 0.0) fail(p + "/transition", "the first part has no transition before it");
        out.handshape = shape(part, p, "handshape", true);
        out.endHandshape = shape(part, p, "endHandshape", false, out.handshape);
        orientation(part, p, "fingers", "palm", out.fingers, out.palm, true);
        glm::dvec3 f = out.fingers, q = out.palm;
        orientation(part, p, "endFingers", "endPalm", f, q, false);
        if (part.contains("endFingers")) out.endFingers = f, out.endPalm = q;
        out.at = place(part, p, "at", "offset");
        out.touch = text(part, p, "touch", "base");
        for (const char* key : {"leftOffset", "endLeftOffset"})
            if (part.contains(key) && relation != HandRelation::Mirrored && relation != HandRelation::Symmetric)
                fail(p + "/" + key, "only mirrored or symmetric hands have the left hand offset from the mirror image");
        if (part.contains("leftOffset")) out.leftOffsetMm = vector3(part["leftOffset"], p + "/leftOffset", kOffsetMm);
        out.endLeftOffsetMm = part.contains("endLeftOffset") ? vector3(part["endLeftOffset"], p + "/endLeftOffset", kOffsetMm) : out.leftOffsetMm;
        if (part.contains("path")) readPath(part["path"], p + "/path", out);
        if (part.contains("hold")) {
            if (out.path == PathShape::None) fail(p + "/hold", "a hold ends a movement: give the part a \"path\"");
            out.holdSeconds = number(part, p, "hold", NumberRange{0.0, std::max(0.0, out.seconds - 0.05), "s"}, 0.0);
        }
        if (part.contains("local")) readLocal(part["local"], p + "/local", out);
        if (part.contains("repeat")) {
            const json& r = part["repeat"];
            const std::string rp = p + "/repeat";
            if (!r.is_object()) fail(rp, "expected {\"count\": 2, \"return\": \"retrace\" | \"lifted\" | \"continue\" | \"trill\"}");
            only(r, rp, {"count", "return", "lift"});
            out.repeat = whole(r, rp, "count", 1, 12, 1);
            static const std::map<std::string, RepeatReturn> modes{{"retrace", RepeatReturn::Retrace},
                                                                   {"lifted", RepeatReturn::Lifted},
                                                                   {"continue", RepeatReturn::Continue},
                                                                   {"trill", RepeatReturn::Trill}};
            out.returns = choose(modes, text(r, rp, "return", "retrace"), rp + "/return");
            if (r.contains("lift")) out.lift = direction(r["lift"], rp + "/lift");
            if (out.returns == RepeatReturn::Continue && out.path != PathShape::Circle)
                fail(rp + "/return", "only a circle continues in the same direction (it closes); use retrace or lifted");
            if (out.repeat > 1 && out.path == PathShape::None)
                fail(rp + "/count", "repeats a path: give one (\"path\"), or repeat a local movement with its \"count\"");
        }
        if (relation == HandRelation::Together && !part.contains("base"))
            fail(p + "/base", "hands moving \"together\" name the left hand's start: {\"handshape\", \"fingers\", \"palm\", \"at\"}");
        if (relation == HandRelation::Base || relation == HandRelation::Together) {
            // A part without one (the first part of HOMEWORK, one-handed HOME) has the base hand
            // wait where the next part needs it.
            if (!part.contains("base")) return finishPart(part, p, out);
            if (!part["base"].is_object()) fail(p + "/base", "expected {\"handshape\", \"fingers\", \"palm\", \"at\"}");
            const json& b = part["base"];
            only(b, p + "/base", {"handshape", "fingers", "palm", "at", "offset", "path", "carried"});
            if (b.contains("path")) {
                const std::string bp = p + "/base/path";
                if (relation == HandRelation::Together) fail(bp, "hands moving \"together\" follow the right hand's path; the left has none of its own");
                NotationPart own;
                readPath(b["path"], bp, own);
                if (own.to) fail(bp + "/to", "a base hand's own path goes in a \"direction\" with a \"size\", or is a circle");
                out.basePath.push_back(own);
            }
            if (b.contains("carried") && b.contains("path"))
                fail(p + "/base/carried", "a carried base hand moves with the dominant hand; it has no path of its own");
            if (b.contains("carried") && relation == HandRelation::Together)
                fail(p + "/base/carried", "hands moving \"together\" are carried already");
            out.baseHandshape = shape(b, p + "/base", "handshape", true);
            orientation(b, p + "/base", "fingers", "palm", out.baseFingers, out.basePalm, true);
            out.baseAt = place(b, p + "/base", "at", "offset");
            if (out.baseAt.onOtherHand()) fail(p + "/base/at", "the base hand is placed on the body or in neutral space");
            if (b.contains("carried")) {
                if (!b["carried"].is_boolean()) fail(p + "/base/carried", "expected true or false");
                out.baseCarried = b["carried"].get<bool>();
            }
        } else if (part.contains("base")) {
            fail(p + "/base", "only a part with \"hands\": \"base\" or \"together\" (its own or the sign's) has a base hand");
        }
        return finishPart(part, p, out);
    }

    NotationPart finishPart(const json& part, const std::string& p, NotationPart& out) const {
        if (part.contains("contact")) {
            const json& c = part["contact"];
            if (!c.is_array() || c.size() > 4) fail(p + "/contact", "expected a list of contact events [{\"at\", \"by\", \"when\"}]");
            for (std::size_t i = 0; i < c.size(); ++i) {
                const std::string cp = p + "/contact/" + std::to_string(i);
                if (!c[i].is_object()) fail(cp, "a contact event is {\"at\": place, \"by\": hand point, \"when\": \"start\" | \"end\" | 0..1}");
                only(c[i], cp, {"at", "offset", "by", "when"});
                NotationContact event;
                event.line = source_.lineAt(cp);
                event.by = text(c[i], cp, "by", out.touch);
                if (c[i].contains("when")) {
                    const json& w = c[i]["when"];
                    if (w.is_string() && w == "start") event.when = 0.0;
                    else if (w.is_string() && w == "end") event.when = 1.0;
                    else if (w.is_number()) event.when = source_.number(w, cp + "/when", NumberRange{0.0, 1.0, ""});
                    else fail(cp + "/when", "expected \"start\", \"end\" or a fraction of the stroke 0..1");
                }
                const NotationPlace where = c[i].contains("at")                    ? place(c[i], cp, "at", "offset")
                                            : event.when < 0.5 || !out.to.has_value() ? out.at
                                                                                      : *out.to;
                if (!c[i].contains("at") && c[i].contains("offset")) fail(cp + "/offset", "an offset goes with its \"at\"");
                event.at = where.name;
                event.offsetMm = where.offsetMm;
                out.contacts.push_back(event);
            }
        }
        if (part.contains("clasp")) {
            if (!part["clasp"].is_boolean()) fail(p + "/clasp", "expected true or false");
            out.clasp = part["clasp"].get<bool>();
            const bool onHand = std::any_of(out.contacts.begin(), out.contacts.end(),
                                            [](const NotationContact& e) { return e.at.rfind("hand:", 0) == 0; });
            if (out.clasp && !onHand)
                fail(p + "/clasp", "a clasp is a contact of the two hands: give a contact event on the other hand (\"hand:...\")");
        }
        return out;
    }

    void readPath(const json& path, const std::string& p, NotationPart& out) const {
        if (!path.is_object()) fail(p, "expected {\"shape\": \"straight\" | \"arc\" | \"circle\" | \"zigzag\" | \"wavy\", ...}");
        only(path, p, {"shape", "to", "toOffset", "direction", "size", "side", "bulge", "plane", "turn", "start"});
        static const std::map<std::string, PathShape> shapes{{"none", PathShape::None},       {"straight", PathShape::Straight},
                                                             {"arc", PathShape::Arc},         {"circle", PathShape::Circle},
                                                             {"zigzag", PathShape::Zigzag},   {"wavy", PathShape::Wavy}};
        out.path = choose(shapes, text(path, p, "shape", ""), p + "/shape");
        out.sizeMm = number(path, p, "size", kSizeMm, 0.0);
        if (out.path == PathShape::Circle) {
            if (out.sizeMm < 10.0) fail(p + "/size", "a circle needs its diameter, 10 mm or more");
            static const std::map<std::string, int> planes{{"frontal", 0}, {"horizontal", 1}, {"sagittal", 2}};
            const int plane = choose(planes, text(path, p, "plane", "frontal"), p + "/plane");
            static const std::map<std::string, bool> turns{{"clockwise", true}, {"counterclockwise", false}};
            const bool clockwise = choose(turns, text(path, p, "turn", "clockwise"), p + "/turn");
            // The plane as its observer sees it (screen right R, screen up U): the viewer for a
            // frontal circle, from above facing forward for a horizontal one, from the signer's
            // right for a sagittal one.
            static const glm::dvec3 R[3] = {{-1, 0, 0}, {1, 0, 0}, {0, 0, 1}};
            static const glm::dvec3 U[3] = {{0, 1, 0}, {0, 0, 1}, {0, 1, 0}};
            glm::dvec3 start = U[plane];
            if (path.contains("start")) start = direction(path["start"], p + "/start");
            const double a = glm::dot(start, R[plane]), b = glm::dot(start, U[plane]);
            if (glm::length(start - a * R[plane] - b * U[plane]) > 0.1 || a * a + b * b < 0.9)
                fail(p + "/start", "where the circle starts must lie in its plane");
            out.side = a * R[plane] + b * U[plane];  // from the centre to the start
            // The first motion: the start turned a quarter, clockwise or not, as the observer sees it.
            out.direction = clockwise ? (b * R[plane] - a * U[plane]) : (-b * R[plane] + a * U[plane]);
            return;
        }
        const bool hasTo = path.contains("to"), hasDirection = path.contains("direction");
        if (out.path != PathShape::None && hasTo == hasDirection)
            fail(p, "give where the path goes: \"to\" a place, or a \"direction\" and a \"size\"");
        if (hasTo) out.to = place(path, p, "to", "toOffset");
        if (hasDirection) {
            out.direction = direction(path["direction"], p + "/direction");
            if (out.sizeMm < 1.0) fail(p + "/size", "a path in a direction needs its size in mm");
        }
        if (path.contains("bulge") && out.path != PathShape::Arc) fail(p + "/bulge", "only an arc has a bulge");
        out.bulgeMm = number(path, p, "bulge", kSizeMm, 0.0);
        if (path.contains("side")) out.side = direction(path["side"], p + "/side");
        else if (out.path == PathShape::Arc || out.path == PathShape::Zigzag || out.path == PathShape::Wavy)
            fail(p + "/side", "an arc, zigzag or wavy path names the side it bulges to (\"up\", \"left\" ...)");
    }

    void readLocal(const json& local, const std::string& p, NotationPart& out) const {
        if (!local.is_object()) fail(p, "expected {\"kind\": \"wiggle\" | \"flick\" | \"bend\" | \"open-close\" | \"twist\" | \"nod\" | \"rub\", ...}");
        only(local, p, {"kind", "with", "count", "degrees"});
        static const std::map<std::string, LocalMovement> kinds{
            {"wiggle", LocalMovement::Wiggle}, {"flick", LocalMovement::Flick}, {"bend", LocalMovement::Bend},
            {"open-close", LocalMovement::OpenClose}, {"twist", LocalMovement::Twist}, {"nod", LocalMovement::Nod},
            {"rub", LocalMovement::Rub}};
        out.local = choose(kinds, text(local, p, "kind", ""), p + "/kind");
        const bool oscillates = out.local == LocalMovement::Wiggle || out.local == LocalMovement::Twist ||
                                out.local == LocalMovement::Nod || out.local == LocalMovement::Rub;
        out.localCount = whole(local, p, "count", 1, 12, oscillates ? 2 : 1);
        out.localDegrees = number(local, p, "degrees", kDegrees, out.local == LocalMovement::Nod ? 30.0 : 60.0);
        if (out.local == LocalMovement::OpenClose && out.localCount > 1 && out.path != PathShape::None)
            fail(p + "/count", "a repeated open-close is a local movement over a still hand: give no path, or repeat the path");
        if (out.local == LocalMovement::Wiggle) out.localWith = shape(local, p, "with", true);
        else if (local.contains("with")) fail(p + "/with", "only a wiggle alternates with another handshape");
        if ((out.local == LocalMovement::Flick || out.local == LocalMovement::Bend || out.local == LocalMovement::OpenClose) &&
            out.endHandshape == out.handshape)
            fail(p + "/kind", "a " + toString(out.local) + " changes the handshape: give the part's \"endHandshape\"");
    }

    NotationProvenance readProvenance(const json& a, const std::string& p, std::size_t parts) const {
        if (!a.is_object()) fail(p, "expected {\"entry\": ASL-LEX EntryID, \"code\": [...], \"durationMs\": ...}");
        only(a, p, {"entry", "variant", "source", "differs", "code", "durationMs"});
        NotationProvenance out;
        out.line = source_.lineAt(p);
        out.entry = text(a, p, "entry", "");
        out.variant = text(a, p, "variant", "");
        out.source = text(a, p, "source", "");
        out.durationMs = number(a, p, "durationMs", kDurationMs, 0.0);
        static const std::set<std::string> fields{"handshape", "signType", "movement", "major", "minor", "nondominant",
                                                  "repeated", "contact", "duration"};
        if (a.contains("differs")) {
            if (!a["differs"].is_array()) fail(p + "/differs", "expected a list of code fields");
            for (std::size_t i = 0; i < a["differs"].size(); ++i) {
                const json& d = a["differs"][i];
                if (!d.is_string() || !fields.count(d.get<std::string>()))
                    fail(p + "/differs/" + std::to_string(i), "expected one of handshape, signType, movement, major, minor, nondominant, repeated, contact, duration");
                out.differs.push_back(d.get<std::string>());
            }
            if (!out.differs.empty() && out.variant.empty()) fail(p + "/variant", "a sign that differs from its entry names the variant it follows");
        }
        if (!out.entry.empty() && !a.contains("code")) fail(p + "/code", "give the entry's ASL-LEX code, one object per part");
        if (a.contains("code")) {
            const json& c = a["code"];
            if (!c.is_array() || c.size() != parts) fail(p + "/code", "expected one code object per part (" + std::to_string(parts) + ")");
            for (std::size_t i = 0; i < c.size(); ++i) {
                const std::string cp = p + "/code/" + std::to_string(i);
                if (!c[i].is_object()) fail(cp, "expected {\"handshape\": ..., \"signType\": ..., ...}");
                only(c[i], cp, {"handshape", "signType", "movement", "major", "minor", "nondominant", "repeated", "contact"});
                AslLexCode code;
                code.handshape = text(c[i], cp, "handshape", "");
                code.signType = text(c[i], cp, "signType", "");
                code.movement = text(c[i], cp, "movement", "");
                code.majorLocation = text(c[i], cp, "major", "");
                code.minorLocation = text(c[i], cp, "minor", "");
                code.nondominant = text(c[i], cp, "nondominant", "");
                code.repeated = whole(c[i], cp, "repeated", 0, 1, -1);
                code.contact = whole(c[i], cp, "contact", 0, 1, -1);
                out.code.push_back(code);
            }
        }
        return out;
    }

    const JsonSource& source_;
    const HandshapeLibrary& shapes_;
};

}  // namespace

std::string toString(HandRelation r) {
    switch (r) {
        case HandRelation::One: return "one";
        case HandRelation::Symmetric: return "symmetric";
        case HandRelation::Mirrored: return "mirrored";
        case HandRelation::Alternating: return "alternating";
        case HandRelation::Base: return "base";
        case HandRelation::Together: return "together";
    }
    return "?";
}

std::string toString(PathShape s) {
    switch (s) {
        case PathShape::None: return "none";
        case PathShape::Straight: return "straight";
        case PathShape::Arc: return "arc";
        case PathShape::Circle: return "circle";
        case PathShape::Zigzag: return "zigzag";
        case PathShape::Wavy: return "wavy";
    }
    return "?";
}

std::string toString(RepeatReturn m) {
    switch (m) {
        case RepeatReturn::Retrace: return "retrace";
        case RepeatReturn::Lifted: return "lifted";
        case RepeatReturn::Continue: return "continue";
        case RepeatReturn::Trill: return "trill";
    }
    return "?";
}

std::string toString(LocalMovement m) {
    switch (m) {
        case LocalMovement::None: return "none";
        case LocalMovement::Wiggle: return "wiggle";
        case LocalMovement::Flick: return "flick";
        case LocalMovement::Bend: return "bend";
        case LocalMovement::OpenClose: return "open-close";
        case LocalMovement::Twist: return "twist";
        case LocalMovement::Nod: return "nod";
        case LocalMovement::Rub: return "rub";
    }
    return "?";
}

SignNotation readSignNotation(const JsonSource& source, const std::string& pointer, const HandshapeLibrary& shapes) {
    return withJsonErrors(source, [&] { return NotationReader(source, shapes).read(pointer); });
}

}  // namespace signstim::stimuli
