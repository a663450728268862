// What the sign-notation tests share (sign_notation_test, _parts_test, _hands_test): the hand
// model and handshape library of the default scenes, a synthetic one-sign lexicon, its parse
// and the error it raises.
#pragma once

#include "stimuli/story/sign_notation_check.hpp"

#include <gtest/gtest.h>

#include <string>

namespace signstim::stimuli::notation_fixture {

inline const hand::HandModel& model() {
    static const hand::HandModel m = hand::buildHandModel();
    return m;
}

inline const HandshapeLibrary& shapes() {
    static const HandshapeLibrary library = loadHandshapes(std::string(SIGNSTIM_SOURCE_DIR) + "/scenes/handshapes.json", model());
    return library;
}

// A synthetic lexicon with one sign GLOSS whose "notation" is `notation` (JSON text).
inline std::string lexiconWith(const std::string& notation) {
    return "{\n"
           "  \"format\": \"signstim-lexicon\",\n"
           "  \"version\": 1,\n"
           "  \"locations\": {\"chin\": [0, 248, 92], \"neutral\": [0, -60, 300], \"neutral-right\": [130, -40, 280]},\n"
           "  \"signs\": [\n"
           "    {\"gloss\": \"GLOSS\",\n"
           "     \"notation\": " + notation + "}\n"
           "  ]\n"
           "}\n";
}

inline Lexicon parse(const std::string& text) { return parseLexicon(parseJsonText(text, "lexicon.json"), shapes(), model()); }

// The error parsing `text` raises (a test failure when it raises none).
inline InputError errorOf(const std::string& text) {
    try {
        parse(text);
    } catch (const InputError& e) {
        return e;
    }
    ADD_FAILURE() << "no error for:\n" << text;
    return InputError("none");
}

}  // namespace signstim::stimuli::notation_fixture
