// Compiled with SWARMDESIGN_SOURCE_DIR and SWARMDESIGN_BINARY defined (tests/CMakeLists.txt).
#include "test_paths.hpp"

namespace sd::test {

const char* source_dir() { return SWARMDESIGN_SOURCE_DIR; }
const char* swarmdesign_binary() { return SWARMDESIGN_BINARY; }

}  // namespace sd::test
