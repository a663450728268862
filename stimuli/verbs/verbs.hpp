#pragma once
// The indicating verbs of SPEC §3.2 as data (scenes/verbs.json): for each verb its class
// (subject + object, or object only), its hands, and its citation (uninflected) form as
// keyframes per hand: time, position and orientation in the signing-space frame
// (stimuli/verbs/signing_space.hpp) and a handshape name per keyframe.
#include "stimuli/json_source.hpp"
#include "stimuli/verbs/polynomial.hpp"

#include <filesystem>
#include <functional>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace signstim::stimuli {

enum class HandSide { Right, Left };
std::string toString(HandSide side);                      // "right" | "left"
std::optional<HandSide> parseHandSide(std::string_view text);  // exact lower case

// Where a hand is: the origin of its palm frame (hand/: the base of the palm, in the palm
// plane) in signing-space millimetres, and the rotation of the palm frame (stimuli/verbs/sora.hpp).
struct HandPose {
    glm::dvec3 positionMm{0.0};
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};
};

// What a sign's citation form touches on purpose ("contact" in scenes/verbs.json and the
// lexicon): the clearance check (signer/clearance.hpp) lets the hands touch each other, or a
// hand the body, only inside such a sign.
struct SignContact {
    bool hands = false;  // the hands touch each other (HELP's fist on the palm, COPY)
    bool body = false;   // a hand touches the body or the head (MY, THANK-YOU, TELL)
    // The hands clasp each other (MARRY's part of HUSBAND, WIFE, BELIEVE): where a hand's curled
    // digits meet the other hand they stop there, as a grip's do, instead of the whole hand
    // being held off (signer/timeline_clip.hpp, settleTouches).
    bool clasp = false;
};

struct VerbKeyframe {
    double timeSeconds = 0.0;  // from the start of the verb
    HandPose pose;
    std::string handshape;     // a name of the handshape library (scenes/)
    int handshapeLine = 0;     // its line and JSON pointer in the verbs file, for messages
    std::string handshapeField;
};

struct VerbDefinition {
    std::string name;       // gloss, upper case: "ASK"
    std::string meaning;    // "ask a question"
    std::string movement;   // SPEC §3.2 description
    Inflection inflection = Inflection::SubjectObject;
    std::vector<HandSide> hands;  // the right (dominant) hand first
    // The keyframe path is played forth and back this many times in all (SCOLD wags: 3).
    int passes = 1;
    SignContact contact;
    // "handsBySide": each hand stands for one referent and starts at it from its own side (MEET:
    // the hands come from the subject and the object and meet). A model trained on examples
    // whose right hand goes to the subject crosses the arms where the subject is left of the
    // object, and the hands start in or pass through each other (issue 21); such a verb's
    // inflected versions ask the model for the pair the other way round there (s < o), so the
    // right hand starts at the right-hand referent.
    bool handsBySide = false;
    // citation[hand][keyframe]; every hand has the same keyframe times.
    std::vector<std::vector<VerbKeyframe>> citation;

    std::size_t keyframeCount() const { return citation.empty() ? 0 : citation.front().size(); }
    std::size_t handCount() const { return hands.size(); }
    int handIndex(HandSide side) const;  // -1 when the verb does not use that hand
    bool objectOnly() const { return inflection == Inflection::ObjectOnly; }
};

struct VerbLibrary {
    std::string sourceFile;
    std::vector<VerbDefinition> verbs;

    const VerbDefinition* find(std::string_view name) const;
    // Throws InputError(file, line, field, "unknown verb 'X' (known: ASK, ...)").
    const VerbDefinition& get(std::string_view name, const std::string& file = "<command line>",
                              int line = 0, const std::string& field = "verb") const;
    std::string knownNames() const;  // "ASK, GIVE, ..."
};

// Loads and validates scenes/verbs.json; every problem is an InputError naming the file, the
// line and the field (as a JSON pointer).
VerbLibrary loadVerbLibrary(const std::filesystem::path& path);
VerbLibrary parseVerbLibrary(const JsonSource& source);

// Checks every handshape name against `isKnown` (the handshape library); throws InputError
// naming the verb, hand and keyframe of the first unknown one.
void checkHandshapeNames(const VerbLibrary& library, const std::function<bool(const std::string&)>& isKnown);

// Reads a 3-vector field written as [x, y, z], each number finite and in `range` (positions:
// kSigningSpacePositionRange; directions: kDirectionComponentRange). `field` is the JSON
// pointer of the array; an element out of range is named by its own pointer and line.
glm::dvec3 readVector3(const JsonSource& source, const nlohmann::json& value,
                       const std::vector<std::string>& anchors, const std::string& field, const NumberRange& range);

// An orientation written either as "orientation": [w, x, y, z] (unit quaternion) or as
// "fingers": [x, y, z] plus "palm": [x, y, z] directions; when both are given they must agree
// within 1°.
glm::dquat readOrientation(const JsonSource& source, const nlohmann::json& object,
                           const std::vector<std::string>& anchors, const std::string& field);

// The optional "contact" of a verb or sign `object`: an array of "hands" and "body" (nothing
// when absent). `pointer` is the JSON pointer of `object`.
SignContact readSignContact(const JsonSource& source, const nlohmann::json& object,
                            const std::vector<std::string>& anchors, const std::string& pointer);

}  // namespace signstim::stimuli
