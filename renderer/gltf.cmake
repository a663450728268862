# glTF/output half of signstim_renderer (owned by the glTF side).
target_sources(signstim_renderer PRIVATE
  ${CMAKE_CURRENT_LIST_DIR}/scene.cpp
  ${CMAKE_CURRENT_LIST_DIR}/view_geometry.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_validate.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_accessors.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_files.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_loader.cpp
  ${CMAKE_CURRENT_LIST_DIR}/animation.cpp
  ${CMAKE_CURRENT_LIST_DIR}/morph.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_morph.cpp
  ${CMAKE_CURRENT_LIST_DIR}/gltf_writer.cpp
  ${CMAKE_CURRENT_LIST_DIR}/image_io.cpp
  ${CMAKE_CURRENT_LIST_DIR}/video_encoder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/video_decoder.cpp
  ${CMAKE_CURRENT_LIST_DIR}/frame_sink.cpp
  ${CMAKE_CURRENT_LIST_DIR}/relay_sinks.cpp
  ${CMAKE_CURRENT_LIST_DIR}/contact_sheet.cpp
  ${CMAKE_CURRENT_LIST_DIR}/drawing_raster.cpp)
