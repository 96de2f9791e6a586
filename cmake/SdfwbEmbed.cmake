# sdfwb_embed_files(TARGET_SOURCE_VAR NAMESPACE BASE_DIR FILES...)
# Generates a .cpp that holds each file's bytes, so built-in GLSL ships inside the binary.
# The generated table maps the path relative to BASE_DIR to its text.
function(sdfwb_embed_files out_var base_dir)
  set(generated ${CMAKE_CURRENT_BINARY_DIR}/EmbeddedFiles.cpp)
  set(inputs)
  foreach(file ${ARGN})
    list(APPEND inputs ${base_dir}/${file})
  endforeach()
  add_custom_command(
    OUTPUT ${generated}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${generated} -DBASE_DIR=${base_dir} "-DFILES=${ARGN}"
            -P ${PROJECT_SOURCE_DIR}/cmake/EmbedFiles.cmake
    DEPENDS ${inputs} ${PROJECT_SOURCE_DIR}/cmake/EmbedFiles.cmake
    COMMENT "Embedding ${CMAKE_CURRENT_SOURCE_DIR} GLSL files"
    VERBATIM)
  set(${out_var} ${generated} PARENT_SCOPE)
endfunction()
