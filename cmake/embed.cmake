# Data compiled into the binary, so it needs no data files at run time. Each call adds one
# generated C++ file to TARGET; the scripts it runs (embed_json_files.cmake,
# embed_text_file.cmake) say what the file defines.
#
# sd_embed_json(TARGET DIR HEADER NAMESPACE TYPE FUNCTION COMMENT):
#   every *.json of DIR as the table  std::span<const TYPE> NAMESPACE::FUNCTION()  (HEADER).
function(sd_embed_json target)
  cmake_parse_arguments(E "" "DIR;HEADER;NAMESPACE;TYPE;FUNCTION;COMMENT" "" ${ARGN})
  file(GLOB files CONFIGURE_DEPENDS ${E_DIR}/*.json)
  set(generated ${CMAKE_CURRENT_BINARY_DIR}/${E_FUNCTION}.cpp)
  add_custom_command(
    OUTPUT ${generated}
    COMMAND ${CMAKE_COMMAND} -DDIR=${E_DIR} -DOUTPUT=${generated} -DHEADER=${E_HEADER} -DNAMESPACE=${E_NAMESPACE}
            -DTYPE=${E_TYPE} -DFUNCTION=${E_FUNCTION} -P ${PROJECT_SOURCE_DIR}/cmake/embed_json_files.cmake
    DEPENDS ${files} ${PROJECT_SOURCE_DIR}/cmake/embed_json_files.cmake
    COMMENT "${E_COMMENT}")
  target_sources(${target} PRIVATE ${generated})
endfunction()

# sd_embed_text(TARGET FILE HEADER NAMESPACE FUNCTION COMMENT):
#   FILE as  std::string_view NAMESPACE::FUNCTION()  (HEADER).
function(sd_embed_text target)
  cmake_parse_arguments(E "" "FILE;HEADER;NAMESPACE;FUNCTION;COMMENT" "" ${ARGN})
  set(generated ${CMAKE_CURRENT_BINARY_DIR}/${E_FUNCTION}.cpp)
  add_custom_command(
    OUTPUT ${generated}
    COMMAND ${CMAKE_COMMAND} -DFILE=${E_FILE} -DOUTPUT=${generated} -DHEADER=${E_HEADER} -DNAMESPACE=${E_NAMESPACE}
            -DFUNCTION=${E_FUNCTION} -P ${PROJECT_SOURCE_DIR}/cmake/embed_text_file.cmake
    DEPENDS ${E_FILE} ${PROJECT_SOURCE_DIR}/cmake/embed_text_file.cmake
    COMMENT "${E_COMMENT}")
  target_sources(${target} PRIVATE ${generated})
  # One long literal: clang's -Wpedantic warns past the standard's 64 kB minimum length.
  set_source_files_properties(${generated} PROPERTIES COMPILE_OPTIONS -Wno-overlength-strings)
endfunction()
