#include "app/commands.hpp"

namespace signstim::app {

// Owned by the render area; commands are added as the area lands.
void registerRenderCommands(Commands&) {}

}  // namespace signstim::app
