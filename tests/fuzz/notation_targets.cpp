// Fuzz target of the sign notation (docs/lexicon.md, stimuli/story/sign_notation.hpp): a
// lexicon file whose signs are read on the shipped lexicon's body locations (as a lab's file
// is), each notation compiled and checked. A refusal names the input; an accepted sign has
// finite keys in increasing time, and its checks run to the end.
#include "stimuli/json_source.hpp"
#include "stimuli/story/sign_notation_check.hpp"
#include "tests/fuzz/fixtures.hpp"
#include "tests/fuzz/fuzz_target.hpp"

#include <string>

using namespace signstim;
using namespace signstim::stimuli;

SIGNSTIM_FUZZ_TARGET(sign_notation) {
    fuzz::expectRefusalOrSuccess("notation.json", [&] {
        const JsonSource source = parseJsonText(std::string(input), "notation.json");
        if (!source.root.is_object() || !source.root.contains("signs") || !source.root["signs"].is_array()) return;
        const nlohmann::json& signs = source.root["signs"];
        for (std::size_t s = 0; s < signs.size() && s < 64; ++s) {
            if (!signs[s].is_object() || !signs[s].contains("notation")) continue;
            const std::string pointer = "/signs/" + std::to_string(s);
            LexiconSign sign;
            sign.gloss = "FUZZ";
            auto notation = std::make_shared<SignNotation>(readSignNotation(source, pointer, fuzz::handshapes()));
            CompiledNotation compiled = compileSignNotation(*notation, fuzz::lexicon().locations, fuzz::handshapes(),
                                                            fuzz::handModel(), source, pointer);
            for (const auto& keys : compiled.keyframes) {
                if (keys.empty()) fuzz::fail("a compiled hand without keys");
                for (std::size_t k = 0; k < keys.size(); ++k) {
                    for (int i = 0; i < 3; ++i) fuzz::requireFinite(keys[k].pose.positionMm[i], "position");
                    for (int i = 0; i < 4; ++i) fuzz::requireFinite(keys[k].pose.orientation[i], "orientation");
                    if (k > 0 && !(keys[k].timeSeconds > keys[k - 1].timeSeconds)) fuzz::fail("compiled key times do not increase");
                }
            }
            if (compiled.keyframes.front().size() < 2) continue;  // the lexicon refuses it
            sign.hands = compiled.hands;
            sign.contact = compiled.contact;
            sign.keyframes = std::move(compiled.keyframes);
            sign.passThrough = std::move(compiled.passThrough);
            sign.contactEvents = std::move(compiled.contacts);
            sign.strokes = std::move(compiled.parts);
            sign.notation = std::move(notation);
            for (const NotationCheck& c : checkSignNotation(sign, fuzz::lexicon(), fuzz::handshapes(), fuzz::handModel()))
                if (c.name.empty()) fuzz::fail("a check without a name");
        }
    });
}
