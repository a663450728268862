# signstim_test_run_command: runs the built `signstim` binary for the CLI tests
# (tests/app/run_command.hpp); link it and the binary is built first.
add_library(signstim_test_run_command STATIC ${CMAKE_CURRENT_LIST_DIR}/run_command.cpp)
target_include_directories(signstim_test_run_command PUBLIC ${PROJECT_SOURCE_DIR})
target_compile_definitions(signstim_test_run_command PRIVATE SIGNSTIM_EXE="$<TARGET_FILE:signstim>")
add_dependencies(signstim_test_run_command signstim)
