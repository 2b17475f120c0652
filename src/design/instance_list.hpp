#pragma once
// irace's global instance list (generateInstances/addInstances in R/irace.R): a concatenation of
// random permutations of the instance indices, each position with its own seed in 1..2^31-1.
// Every configuration evaluated at position k uses the same (instance, seed): common random
// numbers. The list is drawn from its own generator, seeded once from the design's generator, so
// that a checkpoint stores four numbers instead of every seed.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/rng.hpp"

namespace sd::design {

struct InstancePosition {
  std::size_t instance = 0;  // 0-based index into the caller's instances
  std::uint64_t seed = 0;
};

class InstanceList {
 public:
  InstanceList() = default;
  InstanceList(std::size_t n_instances, std::uint64_t stream_seed, bool sample_instances);

  /// Appends ceil(n / n_instances) whole blocks (irace addInstances(n)).
  void append(std::size_t n);
  std::size_t size() const { return positions_.size(); }
  /// 1-based position, as in irace's race tables.
  const InstancePosition& at(std::size_t position) const { return positions_.at(position - 1); }

  std::size_t n_instances() const { return n_instances_; }
  std::uint64_t stream_seed() const { return stream_seed_; }
  bool sample_instances() const { return sample_instances_; }
  std::size_t blocks() const { return blocks_; }
  /// Rebuilds a list from its description (checkpoint restore).
  static InstanceList replay(std::size_t n_instances, std::uint64_t stream_seed, bool sample_instances,
                             std::size_t blocks);

 private:
  void append_block();

  std::size_t n_instances_ = 1;
  std::uint64_t stream_seed_ = 0;
  bool sample_instances_ = true;
  std::size_t blocks_ = 0;
  Rng rng_;
  std::vector<InstancePosition> positions_;
};

}  // namespace sd::design
