# CLI tests of the verb area: run the built `signstim` binary (train, verb, evaluate).
signstim_add_test(signstim_app_verb_tests
  SOURCES verb_cli_test.cpp
  LIBS signstim_stimuli signstim_common nlohmann_json::nlohmann_json signstim_test_run_command
  COST 100)  # VerbCli.Evaluate* ~100 s under ASan
add_dependencies(signstim_app_verb_tests signstim)
# Data-file mistakes as the user meets them (issue 15: exit 2, file and line, no hang).
signstim_add_test(signstim_app_data_errors_tests
  SOURCES data_errors_cli_test.cpp
  LIBS signstim_stimuli signstim_hand signstim_common signstim_test_run_command)
add_dependencies(signstim_app_data_errors_tests signstim)
