# `signstim story` end to end (the built binary, validation on): check, timeline, rendering.
signstim_add_test(signstim_app_story_tests
  SOURCES story_cli_test.cpp
  LIBS nlohmann_json::nlohmann_json signstim_test_run_command)
add_dependencies(signstim_app_story_tests signstim)
