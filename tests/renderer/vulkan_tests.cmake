# signstim_renderer_vk_tests (Vulkan side): golden images, multi-view, validation.
