# signstim_embed_text(TARGET target NAMESPACE ns FILES name=relative/path ...)
# Embeds text files (paths relative to the current source folder) in `target` as
# `extern const std::string_view name` in namespace `ns`, regenerated when a file changes.
# name=first/path+second/path+...: the files joined in that order, byte for byte (a script kept
# in parts by concern and served as one file, e.g. the jsPsych experiment's experiment.js).
function(signstim_embed_text)
  cmake_parse_arguments(ARG "" "TARGET;NAMESPACE" "FILES" ${ARGN})
  set(output ${CMAKE_CURRENT_BINARY_DIR}/generated/${ARG_TARGET}_embedded.cpp)
  set(inputs)
  set(depends)
  foreach(entry ${ARG_FILES})
    string(FIND "${entry}" "=" equals)
    string(SUBSTRING "${entry}" 0 ${equals} name)
    math(EXPR start "${equals} + 1")
    string(SUBSTRING "${entry}" ${start} -1 path)
    string(REPLACE "+" ";" parts "${path}")
    set(absolute)
    foreach(part ${parts})
      list(APPEND absolute ${CMAKE_CURRENT_SOURCE_DIR}/${part})
      list(APPEND depends ${CMAKE_CURRENT_SOURCE_DIR}/${part})
    endforeach()
    string(REPLACE ";" "+" absolute "${absolute}")
    list(APPEND inputs "${name}=${absolute}")
  endforeach()
  string(REPLACE ";" "|" inputs_argument "${inputs}")  # one command argument
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} -DNAMESPACE=${ARG_NAMESPACE} "-DINPUTS=${inputs_argument}"
            -P ${PROJECT_SOURCE_DIR}/cmake/EmbedText.cmake
    DEPENDS ${depends} ${PROJECT_SOURCE_DIR}/cmake/EmbedText.cmake
    COMMENT "embedding ${ARG_FILES}"
    VERBATIM)
  target_sources(${ARG_TARGET} PRIVATE ${output})
endfunction()
