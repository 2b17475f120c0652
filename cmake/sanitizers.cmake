# Hardening builds (scripts/test.sh runs them after the Release suite; see docs/hardening.md).
#   SWARMDESIGN_SANITIZE  "address,undefined" or "thread": everything, tests included, is built
#                         under those sanitizers, and any report fails the run.
#   SWARMDESIGN_FUZZ      builds the libFuzzer targets in fuzz/ (clang only); the libraries get
#                         coverage instrumentation so the fuzzer can steer by it.
set(SWARMDESIGN_SANITIZE "" CACHE STRING "Sanitizers to build with: address,undefined or thread (empty: none)")
option(SWARMDESIGN_FUZZ "Build the libFuzzer targets in fuzz/ (needs clang)" OFF)

if(SWARMDESIGN_SANITIZE)
  add_compile_options(-fsanitize=${SWARMDESIGN_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer -g)
  add_link_options(-fsanitize=${SWARMDESIGN_SANITIZE})
endif()

if(SWARMDESIGN_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SWARMDESIGN_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
