#pragma once
// The sign notation (docs/lexicon.md, issue 22 §1): a lexicon sign written in the terms of sign
// phonology as ASL-LEX 2.0 codes them (Caselli et al. 2017; Sehyr et al. 2021) — per part of
// the sign (a compound has parts): handshape at start and end, orientation, the place (on the
// body, on the other hand or arm, or in neutral space), the path (straight, arc, circle,
// zigzag, wavy), a local movement (wiggle, flick, bend, open/close, twist, nod, rub), its
// repetition and return (retrace, lifted, continue, trill), the two hands' relation
// (one, symmetric, mirrored, alternating, base) and contact as events the motion must reach.
// It is compiled to the keyframes every lexicon sign has (stimuli/story/lexicon.hpp), with the
// keys the hand passes through marked, so stories use it unchanged. Raw keyframes stay the
// escape hatch. Provenance: the ASL-LEX 2.0 entry it follows, its variant and source, and the
// entry's code, which the description's own code (derived, never written twice) must equal
// except where the variant names a difference.
#include "hand/hand_model.hpp"
#include "stimuli/json_source.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <glm/glm.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace signstim::stimuli {

// Together: both hands move as one rigid unit (BABY's cradled arms, LOVE's crossed fists): the
// left hand starts where `base` puts it and keeps its pose relative to the right hand.
enum class HandRelation { One, Symmetric, Mirrored, Alternating, Base, Together };
enum class PathShape { None, Straight, Arc, Circle, Zigzag, Wavy };
enum class RepeatReturn { Retrace, Lifted, Continue, Trill };
enum class LocalMovement { None, Wiggle, Flick, Bend, OpenClose, Twist, Nod, Rub };
std::string toString(HandRelation relation);
std::string toString(PathShape shape);
std::string toString(RepeatReturn mode);
std::string toString(LocalMovement movement);

// A place: a body location of the lexicon ("chin", "cheek-left", "neutral"), or a place on the
// other hand or arm ("hand:palm", "hand:back", "hand:heel", "hand:radial", "hand:ulnar",
// "hand:fingertips", "hand:index" ..., "arm:wrist", "arm:forearm", "arm:elbow"), plus an offset.
struct NotationPlace {
    std::string name;
    glm::dvec3 offsetMm{0.0};
    bool onOtherHand() const { return name.rfind("hand:", 0) == 0 || name.rfind("arm:", 0) == 0; }
};

struct NotationContact {
    // The place the hand reaches (default: the part's start place for an event at the stroke's
    // start, else where the path goes), with its offset (where the surface is).
    std::string at;
    glm::dvec3 offsetMm{0.0};
    std::string by;    // the point of the acting hand that reaches it (a hand point name)
    double when = 1.0; // in the stroke: 0 its start, 1 its end (every repetition)
    int line = 0;
};

struct NotationPart {
    int line = 0;
    // The two hands' relation in this part: its own "hands", else the sign's (a compound such
    // as STUDENT joins a base-hand part to a symmetric one).
    HandRelation hands = HandRelation::One;
    double seconds = 0.0;  // citation time of the part, its repetitions included
    // The hold at the end of the movement, inside `seconds` (a movement-hold: MARRY's hands stay
    // clasped once the quick arc has landed): the strokes take seconds − holdSeconds.
    double holdSeconds = 0.0;
    double transitionSeconds = 0.0;  // from the previous part's end (0 for the first)
    std::string handshape, endHandshape;  // endHandshape == handshape when it does not change
    glm::dvec3 fingers{0.0, 1.0, 0.0}, palm{0.0, 0.0, 1.0};
    std::optional<glm::dvec3> endFingers, endPalm;
    NotationPlace at;
    std::string touch = "base";  // the dominant hand's point that is at `at`
    // Movement.
    PathShape path = PathShape::None;
    std::optional<NotationPlace> to;  // where the path ends, or ...
    glm::dvec3 direction{0.0};        // ... its direction (unit) times
    double sizeMm = 0.0;              // its size (a circle's diameter, an arc's chord)
    glm::dvec3 side{0.0};             // an arc's or zigzag's bulge side; a circle's start side
    double bulgeMm = 0.0;             // an arc's bulge (0: 15 % of its chord, at least 15 mm)
    glm::dvec3 planeNormal{0.0, 0.0, 1.0};  // circle: the axis it turns about (right hand rule)
    LocalMovement local = LocalMovement::None;
    std::string localWith;  // wiggle: the shape alternated with
    int localCount = 0;     // oscillations of the local movement (0: none)
    double localDegrees = 0.0;
    int repeat = 1;
    RepeatReturn returns = RepeatReturn::Retrace;
    glm::dvec3 lift{0.0, 0.0, 1.0};  // a lifted return bulges this way
    // The other hand: its handshape and pose when the relation is Base.
    std::string baseHandshape;
    glm::dvec3 baseFingers{0.0, 0.0, 1.0}, basePalm{0.0, 1.0, 0.0};
    NotationPlace baseAt;
    // The base hand carried by the dominant hand's path (HELP: the palm lifts the fist): it keeps
    // its place relative to the dominant hand instead of holding still.
    bool baseCarried = false;
    // A base hand with its own path ("base": {"path": ...}, its path fields only): it moves along
    // it over each stroke, in step with the dominant hand, and back on its returns (RIGHT, HARD,
    // MARRY: both hands come together; YEAR: both circle). Empty: a still base hand.
    std::vector<NotationPart> basePath;
    // Mirrored or symmetric hands: the left hand's offset from its mirror image (mm, signing
    // space) at the stroke's start and end, changing along the stroke as the hand moves: hands
    // that meet one above the other or one ahead of the other (GET's right fist landing on the
    // left, CHANGE's X hands one over the other), which mirror images cannot.
    glm::dvec3 leftOffsetMm{0.0}, endLeftOffsetMm{0.0};
    std::vector<NotationContact> contacts;
    // The hands clasp each other at this part's contact (MARRY's grip in HUSBAND, WIFE,
    // BELIEVE): their curled digits stop where they meet the other hand (SignContact::clasp).
    bool clasp = false;
    // Whether both hands move (Battison 1978's symmetry condition applies: ASL-LEX codes such a
    // sign SymmetricalOrAlternating, or DominanceViolation when the handshapes differ).
    bool bothHandsMove() const {
        return hands == HandRelation::Together || (hands == HandRelation::Base && !basePath.empty());
    }
};

// Whether the part's local movement oscillates over a still hand: a wiggle, twist, nod or rub,
// or an open-close repeated ("count" 2 or more: BOY, NO), which closes and opens again.
inline bool oscillatesLocally(const NotationPart& p) {
    if (p.local == LocalMovement::OpenClose) return p.localCount > 1;
    return p.localCount > 0 && (p.local == LocalMovement::Wiggle || p.local == LocalMovement::Twist ||
                                p.local == LocalMovement::Nod || p.local == LocalMovement::Rub);
}

// An ASL-LEX 2.0 code of one part (morpheme): its columns' values as ASL-LEX writes them.
struct AslLexCode {
    std::string handshape;      // Handshape.2.0 ("open_b")
    std::string signType;       // SignType.2.0 ("OneHanded")
    std::string movement;       // Movement.2.0 ("Straight", "Curved", "Circular", "Z-shaped", "None")
    std::string majorLocation;  // MajorLocation.2.0 ("Head")
    std::string minorLocation;  // MinorLocation.2.0 ("Chin")
    std::string nondominant;    // NonDominantHandshape.2.0 ("B"), empty for one-handed
    int repeated = -1;          // RepeatedMovement.2.0 (0/1; -1 not stated)
    int contact = -1;           // Contact.2.0
};

struct NotationProvenance {
    std::string entry;    // ASL-LEX 2.0 EntryID ("mother"); empty: none
    std::string variant;  // the variant followed, when it differs from the entry
    std::string source;   // where the form comes from ("ASL-LEX 2.0 video", a dictionary)
    std::vector<std::string> differs;  // code fields the variant differs in ("handshape", ...)
    std::vector<AslLexCode> code;      // the entry's code per part (compounds: M1, M2)
    double durationMs = 0.0;           // SignDuration(ms); 0: not stated
    int line = 0;
};

struct SignNotation {
    HandRelation hands = HandRelation::One;  // the sign's relation, each part's unless it names its own
    std::vector<NotationPart> parts;
    NotationProvenance provenance;
    // Whether any part uses the left hand (then the sign has two hands throughout; in a
    // one-handed part the left hand holds still where it was, or where it is next needed).
    bool twoHanded() const {
        for (const NotationPart& p : parts)
            if (p.hands != HandRelation::One) return true;
        return hands != HandRelation::One;
    }
};

// A contact event of the compiled sign: where the acting hand's point must be, and when.
struct ContactEvent {
    double timeSeconds = 0.0;
    int part = 0;
    int hand = 0;  // index into the sign's hands (0 right)
    std::string at, by;
    glm::dvec3 offsetMm{0.0};
};

// What compiling gives: per hand, keyframes as the lexicon keeps them and which of them the
// hand passes through without stopping (coarticulation keys, sampleTrack); the contact events;
// and the stroke ends the repetitions return to (for the checks).
struct CompiledNotation {
    std::vector<HandSide> hands;
    std::vector<std::vector<VerbKeyframe>> keyframes;
    std::vector<std::vector<bool>> passThrough;
    std::vector<ContactEvent> contacts;
    SignContact contact;
    struct Stroke {
        int part = 0;
        double startSeconds = 0.0, endSeconds = 0.0;  // of the part's strokes and returns
        glm::dvec3 strokeEndMm{0.0};                  // the dominant palm origin at the first stroke's end
        int strokes = 1;
    };
    std::vector<Stroke> parts;
};

// Reads the "notation" object of the sign at `pointer` (errors name the file, line and field).
SignNotation readSignNotation(const JsonSource& source, const std::string& pointer, const HandshapeLibrary& shapes);

// Compiles `notation` with the lexicon's body `locations`; throws InputError at `source`'s
// `pointer` for a place it cannot resolve or a hand point it does not know.
CompiledNotation compileSignNotation(const SignNotation& notation, const std::map<std::string, glm::dvec3>& locations,
                                     const HandshapeLibrary& shapes, const hand::HandModel& model,
                                     const JsonSource& source, const std::string& pointer);

// The point `name` of a hand with `controls` in its palm frame (mm): the lexicon's touch points
// (touchPointNames) and "back", "heel", "radial", "ulnar", "thumb", "index", "middle", "ring",
// "little" (their tips), "wrist", "forearm", "elbow" (along the forearm, the wrist straight).
std::optional<glm::dvec3> handPointMm(const hand::HandModel& model, const hand::HandControls& controls, hand::Side side,
                                      const std::string& name);
// The same point in signing space for a hand at `pose`.
glm::dvec3 handPointInSpace(const HandPose& pose, const glm::dvec3& pointInPalmMm);
const std::vector<std::string>& handPointNames();

}  // namespace signstim::stimuli
