# signstim_cli_rules_tests: the rules every subcommand's command line follows (exit 1 for flag
# mistakes, plain numbers, nothing written), run on the built binary.
signstim_add_test(signstim_cli_rules_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/cli_rules_test.cpp
  LIBS signstim_test_run_command)
