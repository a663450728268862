# signstim_add_shaders(TARGET name SOURCES a.vert b.frag ...)
# Compiles GLSL to SPIR-V with glslangValidator at build time and embeds the words in a
# generated header (<stem>_<stage>_spv as a uint32_t array), so the binary never reads
# shader files at run time.
function(signstim_add_shaders)
  cmake_parse_arguments(ARG "" "TARGET" "SOURCES" ${ARGN})
  set(out_dir ${CMAKE_CURRENT_BINARY_DIR}/generated/shaders)
  file(MAKE_DIRECTORY ${out_dir})
  set(headers)
  # Files the shaders #include (GL_GOOGLE_include_directive): *.glsl beside them.
  file(GLOB includes CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*.glsl)
  foreach(src ${ARG_SOURCES})
    get_filename_component(name ${src} NAME)
    string(REPLACE "." "_" var ${name})
    set(header ${out_dir}/${name}.spv.h)
    add_custom_command(
      OUTPUT ${header}
      COMMAND Vulkan::glslangValidator --target-env vulkan1.3 -V --quiet
              --vn ${var}_spv -o ${header} ${CMAKE_CURRENT_SOURCE_DIR}/${src}
      DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/${src} ${includes}
      COMMENT "glslang ${name}"
      VERBATIM)
    list(APPEND headers ${header})
  endforeach()
  add_custom_target(${ARG_TARGET}_compile DEPENDS ${headers})
  add_library(${ARG_TARGET} INTERFACE)
  add_dependencies(${ARG_TARGET} ${ARG_TARGET}_compile)
  target_include_directories(${ARG_TARGET} INTERFACE ${CMAKE_CURRENT_BINARY_DIR}/generated)
endfunction()
