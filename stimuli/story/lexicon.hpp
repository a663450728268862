#pragma once
// The lexicon: every non-verb sign a story may use (docs/lexicon.md), as data in
// scenes/lexicon.json. A sign is, per hand, keyframes of where the hand is, how it is turned
// and its handshape, in citation timing — the same keyframe form as a verb's citation form
// (stimuli/verbs/verbs.hpp), with two conveniences for authors:
//   "at": a named body location (forehead, chin, chest, ...) instead of coordinates, and
//   "touch": which point of the hand is at that location (index-tip, thumb-tip, palm, ...),
//            so that "the index fingertip touches the chin" is written as such; the loader
//            places the palm frame by the hand model's forward kinematics of the handshape.
// Locations are signing-space millimetres (stimuli/verbs/signing_space.hpp) measured on the
// default signer; a lab with another avatar can move them in the file.
#include "hand/hand_model.hpp"
#include "stimuli/story/handshapes.hpp"
#include "stimuli/story/sign_notation.hpp"
#include "stimuli/verbs/verbs.hpp"

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace signstim::stimuli {

struct LexiconSign {
    std::string gloss;    // "YESTERDAY"
    std::string meaning;  // "the day before today"
    std::vector<HandSide> hands;  // the right (dominant) hand first
    int passes = 1;               // the keyframe path played forth and back this many times
    SignContact contact;          // what the citation form touches on purpose
    // keyframes[hand][k]: positions already resolved to the palm frame's origin.
    std::vector<std::vector<VerbKeyframe>> keyframes;
    std::string file;  // the lexicon file that defines it
    int line = 0;
    // A sign written in the notation (stimuli/story/sign_notation.hpp; null for keyframes): its
    // description, which keys the hand passes through ([hand][k], as keyframes), the contact
    // events its motion reaches, and its strokes (for the checks).
    std::shared_ptr<const SignNotation> notation;
    std::vector<std::vector<bool>> passThrough;
    std::vector<ContactEvent> contactEvents;
    std::vector<CompiledNotation::Stroke> strokes;

    double durationSeconds() const;
};

// A sign or location of the default lexicon that a lab's own lexicon (--lexicon) redefines.
struct LexiconOverride {
    std::string what;  // "sign TEACHER", "location chin"
    std::string file;  // the lab's definition
    int line = 0;
    std::string replacedFile;  // the default one
    int replacedLine = 0;
};

struct Lexicon {
    std::string file;
    std::map<std::string, glm::dvec3> locations;  // name -> signing-space mm
    std::vector<LexiconSign> signs;               // in file order (an override takes the default's place)
    std::vector<LexiconOverride> overrides;       // in the order read

    const LexiconSign* find(std::string_view gloss) const;
    std::vector<std::string> glosses() const;
};

// The point of the hand named `touch` in the palm frame (mm) for `controls`, on `side`:
// "base" (the palm frame's origin), "palm" (the middle of the palmar surface), "knuckles"
// (the middle finger's knuckle), "thumb-tip", "index-tip", "middle-tip", "ring-tip",
// "little-tip", "fingertips" (= middle-tip). Empty optional for an unknown name.
std::optional<glm::dvec3> touchPointMm(const hand::HandModel& model, const hand::HandControls& controls,
                                       hand::Side side, std::string_view touch);
const std::vector<std::string>& touchPointNames();

// Palm-frame origin (signing space) such that the touch point `touchInPalmMm` lies at
// `targetMm` when the palm frame has `orientation` (signing-space convention of
// stimuli/verbs/verbs.hpp: columns palmar x, y = z × x computed in these coordinates, fingers z).
glm::dvec3 palmOriginForTouch(const glm::dvec3& targetMm, const glm::dquat& orientation,
                              const glm::dvec3& touchInPalmMm);

// Loads and validates; handshape names are checked against `shapes`. Errors name the file,
// the line and the field. loadLexicon takes a file or a folder of .json files (read in name
// order; a location may be defined in any of them, a sign only once).
Lexicon parseLexicon(const JsonSource& source, const HandshapeLibrary& shapes, const hand::HandModel& model);
Lexicon loadLexicon(const std::filesystem::path& file, const HandshapeLibrary& shapes, const hand::HandModel& model);
// The default lexicon `base` with a lab's own `lab` (a file or folder; empty: none) on top: the
// lab's signs are added, and a sign or location it defines that `base` defines too replaces
// base's (Lexicon::overrides lists them). Within one of the two, a sign is defined once. The
// lab's signs may use base's locations.
Lexicon loadLexicon(const std::filesystem::path& base, const std::filesystem::path& lab, const HandshapeLibrary& shapes,
                    const hand::HandModel& model);

}  // namespace signstim::stimuli
