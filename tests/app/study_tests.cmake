# `signstim study` end to end (the built binary, validation on): check, render, resume, verify,
# shards and merge, interruption.
signstim_add_test(signstim_app_study_tests
  SOURCES study_cli_test.cpp
  LIBS nlohmann_json::nlohmann_json signstim_test_run_command)
add_dependencies(signstim_app_study_tests signstim)
