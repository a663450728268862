#pragma once
// The handshape library (SPEC §1.6): named McDonald-hand controls stored as data in
// scenes/handshapes.json, validated on load. Errors name the file, the line, the shape and
// the field (signstim::InputError).
//
// File format (see scenes/handshapes.json), "version": 2 required (version 1 thumbs were
// tuned for SPEC §1.4's literal thumb chain and are refused with an explanation):
//   "fingerPresets": {"FC": {"bend": .95, "hook": .8}, ...}          SPEC §1.6 presets
//   "thumbPresets":  {"side": {"bendDeg": 5, "spreadDeg": 12, "mcpDeg": 0, "ipDeg": 0}, ...}
//   "handshapes": [{"name": "A", "aslLex": "A" | null, "description": "...",
//                   "fingers": {"index": "FC" | {"preset"?, "bend"?, "hook"?,
//                                                "spreadDeg"? | "abductionDeg"?}, ...},
//                   "thumb": "side" | {"preset"?, "bendDeg"?, "spreadDeg"?, "mcpDeg"?, "ipDeg"?},
//                   "contact": "middle"   (optional: the thumb tip touches that fingertip)}]
// Abduction α is measured from the palm's z-axis; the stored spread is σ = α − ρ (SPEC §1.6).
#include "hand/hand_model.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace signstim::stimuli {

struct Handshape {
    std::string name;         // "A", "bent-B", "5", ...
    std::string aslLexLabel;  // ASL-LEX 2.0 handshape name; empty where none exists
    std::string description;
    hand::HandControls controls;
    std::optional<hand::Digit> thumbContact;  // fingertip the thumb tip touches, if any
};

struct HandshapeLibrary {
    std::string file;
    std::vector<Handshape> shapes;  // in file order

    const Handshape* find(std::string_view name) const;
    // Like find(), but throws InputError listing the known names.
    const Handshape& at(std::string_view name) const;
};

// `model` provides the radiation angles ρ that turn abduction into spread.
HandshapeLibrary parseHandshapes(const std::string& text, const std::string& fileName,
                                 const hand::HandModel& model);
HandshapeLibrary loadHandshapes(const std::filesystem::path& file, const hand::HandModel& model);

// The handshape file a command reads: `explicitFile` when given (its --shapes option), else
// SCENES/handshapes.json with SCENES = resolveScenesDir(scenesDir) (stimuli/scenes_path.hpp).
std::filesystem::path handshapesFile(const std::filesystem::path& explicitFile,
                                     const std::filesystem::path& scenesDir);

}  // namespace signstim::stimuli
