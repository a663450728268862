# Crash safety (issue 13 §4): SIGKILL at 10 moments per command, one in each tenth of the run; re-runs to the same bytes.
signstim_add_test(signstim_crash_tests
  SOURCES crash_test.cpp
  LIBS signstim_common signstim_test_run_command
  COST 130)  # CrashSafety.Study* ~130 s (tests/CMakeLists.txt: COST)
add_dependencies(signstim_crash_tests signstim)
