# signstim_renderer_vk_tests (Vulkan side): golden images, multi-view, validation.
signstim_add_test(signstim_renderer_vk_tests
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/vk_renderer_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/vk_golden.cpp
    ${CMAKE_CURRENT_LIST_DIR}/vk_raw_baseline_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/vk_morph_test.cpp
  LIBS signstim_renderer OpenImageIO::OpenImageIO nlohmann_json::nlohmann_json)
