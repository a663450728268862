#include "app/commands.hpp"

namespace signstim::app {

void registerDemoCommand(Commands&) {}

}  // namespace signstim::app
