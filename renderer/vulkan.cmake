# Vulkan half of signstim_renderer (owned by the Vulkan side).
target_sources(signstim_renderer PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/vk_check.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vk_instance.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vk_device.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vk_memory.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vk_commands.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vk_descriptors.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vk_pipelines.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vk_targets.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vk_readback.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vk_scene.cpp
  ${CMAKE_CURRENT_LIST_DIR}/label_overlay.cpp
  ${CMAKE_CURRENT_LIST_DIR}/procedural.cpp
  ${CMAKE_CURRENT_LIST_DIR}/renderer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vk_mesh_pipeline.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vk_morph.cpp
  ${CMAKE_CURRENT_LIST_DIR}/vk_raw_baseline.cpp)
