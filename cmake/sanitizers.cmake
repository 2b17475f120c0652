# Hardening builds (scripts/test.sh runs them after the Release suite; see docs/hardening.md).
#   SWARMDESIGN_SANITIZE  "address,undefined" or "thread": everything, tests included, is built
#                         under those sanitizers, and any report fails the run.
#   SWARMDESIGN_FUZZ      builds the libFuzzer targets in fuzz/ (clang only); the libraries get
#                         coverage instrumentation so the fuzzer can steer by it.
set(SWARMDESIGN_SANITIZE "" CACHE STRING "Sanitizers to build with: address,undefined or thread (empty: none)")
option(SWARMDESIGN_FUZZ "Build the libFuzzer targets in fuzz/ (needs clang)" OFF)

# Reports need file and line of every frame, not variables and types: clang's line tables
# alone give them, and compile and link faster than full -g (GCC: -g1).
if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  set(sd_sanitizer_debug -gline-tables-only)
else()
  set(sd_sanitizer_debug -g1)
endif()
if(SWARMDESIGN_SANITIZE)
  add_compile_options(-fsanitize=${SWARMDESIGN_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer ${sd_sanitizer_debug})
  add_link_options(-fsanitize=${SWARMDESIGN_SANITIZE})
endif()

if(SWARMDESIGN_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SWARMDESIGN_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
