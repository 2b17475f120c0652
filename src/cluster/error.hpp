#pragma once
// The one exception this folder throws for trouble on the cluster side.
#include <stdexcept>

namespace sd::cluster {

/// A failure talking to a cluster, as one line that names the host and what went wrong.
struct ClusterError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace sd::cluster
