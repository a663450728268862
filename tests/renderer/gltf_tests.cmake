# signstim_renderer_gltf_tests (glTF side): scene maths, loader, broken input, animation,
# writer round trip, image files, video, frame sinks.
signstim_add_test(signstim_renderer_gltf_tests
  SOURCES
    ${CMAKE_CURRENT_LIST_DIR}/scene_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gltf_loader_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gltf_validate_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/output_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/contact_sheet_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/animation_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/morph_test.cpp
    ${CMAKE_CURRENT_LIST_DIR}/gltf_writer_test.cpp
  LIBS signstim_renderer OpenImageIO::OpenImageIO nlohmann_json::nlohmann_json TinyGLTF::TinyGLTF)
