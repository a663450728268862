# signstim_cli_values_tests: the shared command-line value parsers (app/cli_values.hpp).
signstim_add_test(signstim_cli_values_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/cli_values_test.cpp
  LIBS signstim_app)
