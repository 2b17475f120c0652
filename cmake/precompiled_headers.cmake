# Precompiled headers: the heaviest headers parsed once per build tree instead of once per
# file. Measured on the 2-core test machine:
# - GCC (the Release tree): compiling nothing but nlohmann/json takes 1.7 s, pybind11 4.6 s and
#   CLI11 5.7 s, yet a whole file's compile is mostly GCC optimising our code at -O3: the
#   precompiled headers take 15 % off the libraries' compile time (919 to 780 CPU seconds) and
#   0-20 % off a test's, so the GCC tests do without them (their own code compiles at -O1).
# - Clang at -O1 (the sanitizer trees): parsing is half a file's compile, and a header of the
#   standard set, nlohmann/json and GoogleTest takes 25-40 % off a test's compile (objective_test
#   7.4 to 4.5 s, sensors_test 6.3 to 3.9 s) and 10-30 % off a library file's, so there the tests
#   reuse one too.
# Sources still include what they use: clang-tidy (scripts/tidy.sh) reads every file without
# them, so a missing include fails there.
#
# A precompiled header is valid only for the flags it was made with, so one host target makes
# it for every library and they reuse it (REUSE_FROM), another for every test; the swarmdesign
# executable (CLI11) and the Python module (pybind11) make their own. It changes parsing only,
# never code: no score moves.
option(SWARMDESIGN_PCH "Precompile the heaviest headers (GCC and Clang builds)" ON)
if(NOT CMAKE_CXX_COMPILER_ID MATCHES "^(GNU|Clang)$")
  set(SWARMDESIGN_PCH OFF)
endif()
set(SD_TEST_PCH OFF)
if(SWARMDESIGN_PCH AND CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  set(SD_TEST_PCH ON)
  # Clang stamps a precompiled header with its inputs' modification times and refuses it when
  # they differ; a header ccache restores into a fresh clone would be refused. ccache's advice.
  add_compile_options("SHELL:-Xclang -fno-pch-timestamp")
endif()

# Clang can also compile, once, the code of the inline functions and templates a precompiled
# header holds (-fpch-codegen) into an object of its own; the files that use the header then
# call that code instead of each optimising and instrumenting a copy of it. In the sanitizer
# trees that copy was most of a file's compile: a CLI file (CLI11) 13.5 to 7.3 s, a test
# (GoogleTest, nlohmann/json) 10.9 to 8.9 s, for 20-40 s once per header. The code is the same
# code, compiled with the same flags (the object's functions are weak, as inline ones are).
# That object holds every inline function of the headers, a few of which call libstdc++
# internals that are never defined (std::filesystem::path's _List::type): linked by lld with
# --gc-sections, only the code something calls is kept, so it needs lld (which also links the
# sanitizer trees' large executables faster than ld).
option(SWARMDESIGN_PCH_CODEGEN "Clang trees: compile the precompiled headers' code once (needs lld)" ON)
set(SD_PCH_CODEGEN OFF)
if(SD_TEST_PCH AND SWARMDESIGN_PCH_CODEGEN)
  find_program(SD_LLD ld.lld)
  if(SD_LLD)
    set(SD_PCH_CODEGEN ON)
    add_link_options(-fuse-ld=lld LINKER:--gc-sections)
  endif()
endif()

set(SD_PCH_STANDARD <algorithm> <array> <chrono> <cmath> <cstdint> <filesystem> <fstream> <functional>
    <iostream> <map> <memory> <mutex> <optional> <set> <span> <sstream> <stdexcept> <string>
    <string_view> <thread> <vector>)

# sd_pch_code(HOST): HOST's precompiled header is made with -fpch-codegen, and the target
# HOST_code holds the object its code compiles to. It is a target of its own because every
# compile of HOST, its header's included, waits for HOST's own custom commands.
function(sd_pch_code host)
  if(NOT SD_PCH_CODEGEN)
    return()
  endif()
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/CMakeFiles/${host}.dir)
  set_source_files_properties(${dir}/cmake_pch.hxx.cxx PROPERTIES COMPILE_OPTIONS -fpch-codegen)
  string(TOUPPER "${CMAKE_BUILD_TYPE}" config)
  separate_arguments(flags UNIX_COMMAND "${CMAKE_CXX_FLAGS} ${CMAKE_CXX_FLAGS_${config}}")
  # The header's own options ("SHELL:" ones are written out below), so the code is compiled
  # as it would have been in each file.
  set(options "$<FILTER:$<TARGET_PROPERTY:${host},COMPILE_OPTIONS>,EXCLUDE,^SHELL:>")
  add_custom_command(OUTPUT ${dir}/pch_code.o
    COMMAND ${CMAKE_CXX_COMPILER} ${flags} ${options} -Xclang -fno-pch-timestamp
            ${CMAKE_CXX20_STANDARD_COMPILE_OPTION} -c ${dir}/cmake_pch.hxx.pch -o ${dir}/pch_code.o
    DEPENDS ${dir}/cmake_pch.hxx.pch
    COMMAND_EXPAND_LISTS VERBATIM
    COMMENT "Compiling the code of ${host}'s precompiled header")
  add_library(${host}_code STATIC ${dir}/pch_code.o)
  set_target_properties(${host}_code PROPERTIES LINKER_LANGUAGE CXX)
endfunction()

# sd_link_pch_code(TARGET HOST): TARGET, which uses HOST's precompiled header, links its code.
# By file, not by target: a target's compiles wait for its link dependencies' custom commands,
# and HOST_code's waits for the header TARGET compiles with (a cycle).
function(sd_link_pch_code target host)
  if(SD_PCH_CODEGEN)
    target_link_libraries(${target} PRIVATE "$<TARGET_FILE:${host}_code>")
  endif()
endfunction()

if(SWARMDESIGN_PCH)
  add_library(sd_pch_library STATIC ${PROJECT_SOURCE_DIR}/cmake/pch_host.cpp)
  target_link_libraries(sd_pch_library PRIVATE sd_warnings nlohmann_json::nlohmann_json)
  target_precompile_headers(sd_pch_library PRIVATE ${SD_PCH_STANDARD} <nlohmann/json.hpp>)
  sd_pch_code(sd_pch_library)
endif()

# sd_test_pch_host(): the tests' host, with the test executables' own flags; tests/CMakeLists.txt
# makes it once GoogleTest is found (a build without tests needs no GoogleTest).
function(sd_test_pch_host)
  if(SD_TEST_PCH)
    add_library(sd_pch_tests STATIC ${PROJECT_SOURCE_DIR}/cmake/pch_host.cpp)
    target_link_libraries(sd_pch_tests PRIVATE sd_warnings nlohmann_json::nlohmann_json GTest::gtest)
    target_precompile_headers(sd_pch_tests PRIVATE ${SD_PCH_STANDARD} <nlohmann/json.hpp> <gtest/gtest.h>)
    sd_pch_code(sd_pch_tests)
  endif()
endfunction()

# sd_use_test_pch(TARGET): a test executable reuses the tests' precompiled header.
function(sd_use_test_pch target)
  if(SD_TEST_PCH)
    target_precompile_headers(${target} REUSE_FROM sd_pch_tests)
    sd_link_pch_code(${target} sd_pch_tests)
  endif()
endfunction()

# sd_use_library_pch(TARGET): TARGET reuses the libraries' precompiled header.
function(sd_use_library_pch target)
  if(SWARMDESIGN_PCH)
    target_precompile_headers(${target} REUSE_FROM sd_pch_library)
    sd_link_pch_code(${target} sd_pch_library)
  endif()
endfunction()

# sd_own_pch(TARGET HEADERS...): TARGET makes its own, of the standard set and HEADERS.
function(sd_own_pch target)
  if(SWARMDESIGN_PCH)
    target_precompile_headers(${target} PRIVATE ${SD_PCH_STANDARD} ${ARGN})
    sd_pch_code(${target})
    sd_link_pch_code(${target} ${target})
  endif()
endfunction()

# sd_without_pch(FILES...): files compiled without it. GCC 12 forgets, for code inlined from a
# precompiled header, that it came from a system header, and reports its own false positives
# in libstdc++'s string copies there (-Warray-bounds, fatal under -Werror).
function(sd_without_pch)
  set_source_files_properties(${ARGN} PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
endfunction()
