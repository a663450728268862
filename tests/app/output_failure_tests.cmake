# signstim_output_failure_tests: every failed write and signals, end to end (the built
# binary): full disk (tmpfs; skipped with the reason where mounting is not allowed), stdout on
# /dev/full, unknown output names, frame folders, SIGINT/SIGTERM mid-render (docs/errors.md).
signstim_add_test(signstim_output_failure_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/output_failure_test.cpp
  LIBS signstim_test_run_command)
target_compile_definitions(signstim_output_failure_tests PRIVATE SIGNSTIM_EXE="$<TARGET_FILE:signstim>")
add_dependencies(signstim_output_failure_tests signstim)
