#include "app/commands.hpp"

namespace signstim::app {

// Owned by the avatar area; commands are added as the area lands.
void registerAvatarCommands(Commands&) {}

}  // namespace signstim::app
