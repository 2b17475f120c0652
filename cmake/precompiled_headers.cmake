# Precompiled headers: the heaviest headers parsed once per build tree instead of once per
# file (compiling nothing but nlohmann/json takes 1.7 s on the test machine, GoogleTest 1.1-1.5 s,
# pybind11 4.6 s, CLI11 5.7 s). Sources still include what they use: clang-tidy (scripts/tidy.sh)
# reads every file without them, so a missing include fails there.
#
# A precompiled header is only valid for the flags it was made with, so one host target per
# kind of object makes it and the others reuse it (REUSE_FROM):
#   sd_pch_library  every sd_* library (static, -fPIC when the Python module is built)
#   sd_pch_test     every test executable (-fPIE), with GoogleTest
#   the swarmdesign executable (CLI11) and the Python module (pybind11) make their own.
# It changes parsing only, never code: no score moves.
option(SWARMDESIGN_PCH "Precompile the heaviest headers" ON)

set(SD_PCH_STANDARD <algorithm> <array> <chrono> <cmath> <cstdint> <filesystem> <fstream> <functional>
    <iostream> <map> <memory> <mutex> <optional> <set> <span> <sstream> <stdexcept> <string>
    <string_view> <thread> <vector>)
set(sd_pch_host_source ${PROJECT_SOURCE_DIR}/cmake/pch_host.cpp)

if(SWARMDESIGN_PCH)
  add_library(sd_pch_library STATIC ${sd_pch_host_source})
  target_link_libraries(sd_pch_library PRIVATE sd_warnings nlohmann_json::nlohmann_json)
  target_precompile_headers(sd_pch_library PRIVATE ${SD_PCH_STANDARD} <nlohmann/json.hpp>)
endif()

# sd_use_pch(TARGET KIND): TARGET reuses the precompiled header of KIND (library or test).
function(sd_use_pch target kind)
  if(SWARMDESIGN_PCH)
    target_precompile_headers(${target} REUSE_FROM sd_pch_${kind})
  endif()
endfunction()

# sd_own_pch(TARGET HEADERS...): TARGET makes its own, of the standard set and HEADERS.
function(sd_own_pch target)
  if(SWARMDESIGN_PCH)
    target_precompile_headers(${target} PRIVATE ${SD_PCH_STANDARD} ${ARGN})
  endif()
endfunction()
