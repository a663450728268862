# Vulkan half of signstim_renderer (owned by the Vulkan side).
target_sources(signstim_renderer PRIVATE)
