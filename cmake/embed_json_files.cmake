# Writes OUTPUT: a C++ file that holds every *.json file of DIR (not its subfolders) as a
# string, so the binary needs no data files at run time. The table it defines is
#   std::span<const TYPE> FUNCTION()  in namespace NAMESPACE, declared in HEADER,
# with TYPE = {std::string_view name (file name without .json), std::string_view json}.
# Run at build time by sd_embed_json() (cmake/embed.cmake), for the mission catalogue, the
# Arlequin weights, EvoStick's training arenas and the pseudo-reality specifications.
file(GLOB json_files ${DIR}/*.json)
list(SORT json_files)
# The comment names the folder as the repository does, not by its absolute path: the file is
# then the same in every clone, and ccache reuses its object.
get_filename_component(dir_name ${DIR} NAME)
set(body "// Generated from ${dir_name}/*.json by embed_json_files.cmake; do not edit.\n#include \"${HEADER}\"\n\nnamespace ${NAMESPACE} {\nnamespace {\n")
set(table "")
set(index 0)
foreach(file ${json_files})
  get_filename_component(name ${file} NAME_WE)
  file(READ ${file} content)
  string(APPEND body "constexpr char file_${index}[] = R\"SDJSON(${content})SDJSON\";\n")
  string(APPEND table "    {\"${name}\", file_${index}},\n")
  math(EXPR index "${index} + 1")
endforeach()
if(index EQUAL 0)
  string(APPEND body "}  // namespace\n\nstd::span<const ${TYPE}> ${FUNCTION}() { return {}; }\n\n}  // namespace ${NAMESPACE}\n")
else()
  string(APPEND body "constexpr ${TYPE} table[] = {\n${table}};\n}  // namespace\n\nstd::span<const ${TYPE}> ${FUNCTION}() { return table; }\n\n}  // namespace ${NAMESPACE}\n")
endif()
file(WRITE ${OUTPUT}.tmp "${body}")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
