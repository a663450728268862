# signstim_arm_tests (avatar area): arm IK and gaze.
signstim_add_test(signstim_arm_tests
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/arm_ik_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/gaze_test.cpp
  LIBS signstim_hand)
