# CLI tests of the hand area: run the built `signstim` binary.
signstim_add_test(signstim_hand_cli_tests
  SOURCES hand_cli_test.cpp
  LIBS signstim_stimuli signstim_hand signstim_common nlohmann_json::nlohmann_json signstim_test_run_command)
add_dependencies(signstim_hand_cli_tests signstim)
