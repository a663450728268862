#pragma once
// The signer: an avatar and its rig (signer/signer_pose.hpp).
#include "signer/signer_pose.hpp"
#include "renderer/scene.hpp"

#include <filesystem>

namespace signstim::signer {

// The default signer (or a user's avatar) with its rig, loaded once. Not copyable: the rig
// refers to the avatar scene. The handshape library is not the signer's: a story's timeline
// carries its hands' controls (stimuli/story/timeline.hpp); a verb clip is given the library.
class Signer {
public:
    // scenes/avatar/signer.glb unless `avatarFile` is given. Throws InputError naming the file
    // for any problem.
    explicit Signer(const std::filesystem::path& scenesDir, const std::filesystem::path& avatarFile = {},
                    const BoneMapping& mapping = {});
    Signer(const Signer&) = delete;
    Signer& operator=(const Signer&) = delete;

    const render::Scene& avatar() const { return avatar_; }
    const SignerRig& rig() const { return rig_; }

private:
    render::Scene avatar_;
    SignerRig rig_;
};

}  // namespace signstim::signer
