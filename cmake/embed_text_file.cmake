# Writes OUTPUT: a C++ file that holds the text of FILE as a string, so the binary needs no
# data file at run time. It defines  std::string_view FUNCTION()  in namespace NAMESPACE,
# declared in HEADER. Used for Demiurge's grey-floor sample tables (src/modules).
file(READ ${FILE} content)
get_filename_component(name ${FILE} NAME)
set(body "// Generated from ${name} by embed_text_file.cmake; do not edit.\n#include \"${HEADER}\"\n\nnamespace ${NAMESPACE} {\nnamespace {\nconstexpr char text[] = R\"SDTEXT(${content})SDTEXT\";\n}  // namespace\n\nstd::string_view ${FUNCTION}() { return {text, sizeof text - 1}; }\n\n}  // namespace ${NAMESPACE}\n")
file(WRITE ${OUTPUT}.tmp "${body}")
file(COPY_FILE ${OUTPUT}.tmp ${OUTPUT} ONLY_IF_DIFFERENT)
