#pragma once
// The face of a signer avatar: the blend shapes the default signer has (ARKit-52 names, the
// names of the non-manual seam, stimuli/story/timeline.hpp), and the name map that lets an
// avatar with VRM expressions instead (VRM 0.x blendShapeMaster presets, VRM 1.0 expressions)
// show the same non-manuals. docs/avatar-face.md.
#include "renderer/scene.hpp"

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace signstim::signer {

// The morph targets of the default signer's face mesh, in target order (ARKit-52 names).
const std::vector<std::string>& faceTargetNames();

// One ARKit blendshape shown by a VRM expression: `expression` at `weight` × the ARKit weight.
struct FaceMapEntry {
    std::string arkit;
    std::string expression;  // VRM 1.0 name; the VRM 0.x preset is vrm0Preset(expression)
    float weight = 1.0f;
};
// The documented map (docs/avatar-face.md, "The name map"), in a fixed order.
const std::vector<FaceMapEntry>& vrmFaceMap();
// The VRM 0.x blendShapeMaster preset name of a VRM 1.0 expression ("aa" -> "a", "blink" ->
// "blink", "happy" -> "joy", "relaxed" -> "fun", "angry" -> "angry", ...).
std::string vrm0Preset(const std::string& vrm1Expression);

// Every morph target name of the scene's meshes.
std::set<std::string> morphTargetNames(const render::Scene& scene);

// The face weights for an avatar whose morph targets are `targets`: an ARKit name the avatar
// has is passed through; one it lacks is shown through vrmFaceMap() by the VRM 1.0 expression
// or its VRM 0.x preset name, whichever the avatar has (matched without regard to case, as
// exporters vary: "Blink_L", "blink_l"); an expression driven by several ARKit shapes takes the
// largest. Names the avatar has under neither are dropped. Weights stay in [0, 1].
std::map<std::string, float, std::less<>> mapFaceWeights(const std::map<std::string, float>& arkit,
                                                          const std::set<std::string>& targets);

}  // namespace signstim::signer
