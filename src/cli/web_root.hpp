#pragma once
// Where the web app's pages are, for run-exp and report when no --web-root is given.
#include <string>

namespace sd::cli {

/// Beside an installed binary (<prefix>/bin/swarmdesign finds <prefix>/share/swarmdesign/web-root,
/// as `cmake --install` and the .deb lay it out), else the build tree the binary was built in.
std::string default_web_root();

}  // namespace sd::cli
