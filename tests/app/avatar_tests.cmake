# signstim_avatar_tests (avatar area): default avatar skeleton and skin, posing, bring-your-own
# avatars, regeneration, golden images.
signstim_add_test(signstim_avatar_tests
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/avatar_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/signer_pose_test.cpp
    ${CMAKE_CURRENT_SOURCE_DIR}/avatar_render_test.cpp
    ${PROJECT_SOURCE_DIR}/tests/renderer/vk_golden.cpp
  LIBS signstim_app OpenImageIO::OpenImageIO)
