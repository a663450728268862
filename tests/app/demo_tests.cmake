# signstim_demo_tests (lead): verb performances -> signer frames, and the demo job.
signstim_add_test(signstim_demo_tests
  SOURCES
    ${CMAKE_CURRENT_SOURCE_DIR}/verb_render_test.cpp
  LIBS signstim_app OpenImageIO::OpenImageIO)
