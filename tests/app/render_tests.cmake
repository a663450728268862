# render area: end-to-end tests of `signstim render-gltf` (runs the binary; Vulkan with the
# validation layer via SIGNSTIM_VALIDATION=1).
signstim_add_test(signstim_render_cli_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/render_gltf_test.cpp
  LIBS signstim_renderer signstim_test_run_command nlohmann_json::nlohmann_json)
add_dependencies(signstim_render_cli_tests signstim)
