#include "app/commands.hpp"

namespace signstim::app {

// Owned by the Vulkan side: `devices` and `bench render`.
void registerRenderBenchCommands(Commands&) {}

}  // namespace signstim::app
