# signstim_demo_tests (lead): the demo job and `verb --out` end to end (the built binary,
# validation on).
signstim_add_test(signstim_demo_tests
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/demo_cli_test.cpp
  LIBS signstim_app signstim_test_run_command OpenImageIO::OpenImageIO)
