#include "signer/signer.hpp"

#include "signer/avatar_render.hpp"

namespace signstim::signer {

Signer::Signer(const std::filesystem::path& scenesDir, const std::filesystem::path& avatarFile,
               const BoneMapping& mapping)
    : avatar_(loadSignerAvatar(avatarFile.empty() ? defaultAvatarPath(scenesDir) : avatarFile, mapping)),
      rig_(avatar_, mapping) {}

}  // namespace signstim::signer
