#pragma once
// Where the tests find the repository's files and the built program. Both are compiled into
// one small library (test_paths.cpp), not into every test's command line, so that a test's
// object is the same in any clone of the repository and ccache reuses it.

namespace sd::test {

/// The repository's root (missions/, data/, tests/data/, ...).
const char* source_dir();
/// The swarmdesign executable of this build tree.
const char* swarmdesign_binary();

}  // namespace sd::test
