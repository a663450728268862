#include "app/commands.hpp"

namespace signstim::app {

// Owned by the hand area; commands are added as the area lands.
void registerHandCommands(Commands&) {}

}  // namespace signstim::app
