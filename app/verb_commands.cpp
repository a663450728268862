#include "app/commands.hpp"

namespace signstim::app {

// Owned by the verb area; commands are added as the area lands.
void registerVerbCommands(Commands&) {}

}  // namespace signstim::app
