# `signstim story` end to end (the built binary, validation on): check, timeline, rendering.
signstim_add_test(signstim_app_story_tests
  SOURCES story_cli_test.cpp
  LIBS nlohmann_json::nlohmann_json signstim_test_run_command)
add_dependencies(signstim_app_story_tests signstim)

# `signstim sign` (issue 22 §4): one lexicon sign, its claimed code and checks, its contact sheet.
signstim_add_test(signstim_app_sign_tests
  SOURCES sign_cli_test.cpp
  LIBS signstim_test_run_command)
add_dependencies(signstim_app_sign_tests signstim)
