#include "signer/avatar_face.hpp"

#include <algorithm>
#include <cctype>

namespace signstim::signer {

const std::vector<std::string>& faceTargetNames() {
    // ARKit-52 names (Apple, ARFaceAnchor.BlendShapeLocation) of the shapes the default signer
    // has; eyeLookIn/Out and the jaw's forward and sideways shapes are left out (the eye bones
    // turn the eyes; the file's size: scenes/avatar/signer.glb stays under 2 MiB).
    static const std::vector<std::string> names{
        "browInnerUp",     "browDownLeft",     "browDownRight",    "browOuterUpLeft",   "browOuterUpRight",
        "eyeBlinkLeft",    "eyeBlinkRight",    "eyeSquintLeft",    "eyeSquintRight",    "eyeWideLeft",
        "eyeWideRight",    "cheekSquintLeft",  "cheekSquintRight", "cheekPuff",         "noseSneerLeft",
        "noseSneerRight",  "jawOpen",          "mouthClose",       "mouthFunnel",       "mouthPucker",
        "mouthStretchLeft", "mouthStretchRight", "mouthPressLeft", "mouthPressRight",   "mouthSmileLeft",
        "mouthSmileRight", "mouthFrownLeft",   "mouthFrownRight",  "mouthUpperUpLeft",  "mouthUpperUpRight",
        "mouthRollLower",  "tongueOut",
        // Added after the first 32 (their order kept): the lids' share of a look up or down,
        // and the rest of the mouth (mouthShrugLower: the lower lip of MM, docs/nonmanuals.md).
        "eyeLookUpLeft", "eyeLookUpRight", "eyeLookDownLeft", "eyeLookDownRight", "mouthShrugLower",
        "mouthShrugUpper", "mouthRollUpper", "mouthLowerDownLeft", "mouthLowerDownRight", "mouthDimpleLeft",
        "mouthDimpleRight", "mouthLeft", "mouthRight"};
    return names;
}

const std::vector<FaceMapEntry>& vrmFaceMap() {
    // [D] VRM's expressions are whole-face presets, so each ARKit shape borrows the one whose
    // look contains it, at the weight that shows about as much of it (docs/avatar-face.md).
    // Several entries for one ARKit name: the first the avatar has is used.
    static const std::vector<FaceMapEntry> map{
        {"eyeBlinkLeft", "blinkLeft", 1.0f},  {"eyeBlinkLeft", "blink", 1.0f},
        {"eyeBlinkRight", "blinkRight", 1.0f}, {"eyeBlinkRight", "blink", 1.0f},
        {"jawOpen", "aa", 1.0f},
        {"mouthFunnel", "oh", 1.0f},
        {"mouthPucker", "ou", 1.0f},
        {"mouthStretchLeft", "ih", 0.6f},      {"mouthStretchRight", "ih", 0.6f},
        {"mouthSmileLeft", "happy", 0.6f},     {"mouthSmileRight", "happy", 0.6f},
        {"mouthFrownLeft", "sad", 0.6f},       {"mouthFrownRight", "sad", 0.6f},
        {"browInnerUp", "surprised", 0.6f},
        {"browOuterUpLeft", "surprised", 0.5f}, {"browOuterUpRight", "surprised", 0.5f},
        {"eyeWideLeft", "surprised", 0.4f},    {"eyeWideRight", "surprised", 0.4f},
        {"browDownLeft", "angry", 0.7f},       {"browDownRight", "angry", 0.7f},
    };
    return map;
}

std::string vrm0Preset(const std::string& e) {
    // VRM 0.x blendShapeMaster presetName values (VRM 0.x specification, BlendShapePreset).
    static const std::map<std::string, std::string> presets{
        {"aa", "a"},        {"ih", "i"},          {"ou", "u"},          {"ee", "e"},         {"oh", "o"},
        {"blink", "blink"}, {"blinkLeft", "blink_l"}, {"blinkRight", "blink_r"}, {"happy", "joy"},
        {"angry", "angry"}, {"sad", "sorrow"},    {"relaxed", "fun"},   {"neutral", "neutral"},
        {"lookUp", "lookup"}, {"lookDown", "lookdown"}, {"lookLeft", "lookleft"}, {"lookRight", "lookright"}};
    const auto it = presets.find(e);
    return it == presets.end() ? e : it->second;  // "surprised": no 0.x preset; a custom clip of that name
}

std::set<std::string> morphTargetNames(const render::Scene& scene) {
    std::set<std::string> names;
    for (const render::Mesh& mesh : scene.meshes) names.insert(mesh.targetNames.begin(), mesh.targetNames.end());
    return names;
}

namespace {
std::string folded(std::string s) {
    s.erase(std::remove(s.begin(), s.end(), '_'), s.end());
    for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}
}  // namespace

std::map<std::string, float, std::less<>> mapFaceWeights(const std::map<std::string, float>& arkit,
                                                          const std::set<std::string>& targets) {
    std::map<std::string, std::string> byFolded;  // folded name -> the avatar's spelling (first in order)
    for (const std::string& t : targets) byFolded.emplace(folded(t), t);
    const auto find = [&](const std::string& name) -> const std::string* {
        const auto it = byFolded.find(folded(name));
        return it == byFolded.end() ? nullptr : &it->second;
    };
    std::map<std::string, float, std::less<>> out;
    const auto put = [&](const std::string& name, float w) {
        w = std::clamp(w, 0.0f, 1.0f);
        auto [it, inserted] = out.emplace(name, w);
        if (!inserted) it->second = std::max(it->second, w);
    };
    for (const auto& [name, weight] : arkit) {
        if (const std::string* own = find(name)) {  // the avatar has the ARKit shape itself
            put(*own, weight);
            continue;
        }
        for (const FaceMapEntry& entry : vrmFaceMap()) {
            if (entry.arkit != name) continue;
            const std::string* target = find(entry.expression);
            if (!target) target = find(vrm0Preset(entry.expression));
            if (!target) continue;
            put(*target, weight * entry.weight);
            break;
        }
    }
    return out;
}

}  // namespace signstim::signer
