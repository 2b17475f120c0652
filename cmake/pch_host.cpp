// The source of the targets that only make a precompiled header for others to reuse
// (cmake/precompiled_headers.cmake): the header is all they compile.
