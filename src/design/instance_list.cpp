#include "design/instance_list.hpp"

#include <numeric>
#include <stdexcept>

namespace sd::design {

InstanceList::InstanceList(std::size_t n_instances, std::uint64_t stream_seed, bool sample_instances)
    : n_instances_(n_instances), stream_seed_(stream_seed), sample_instances_(sample_instances), rng_(stream_seed) {
  if (n_instances == 0) throw std::invalid_argument("the instance list needs at least one instance");
}

void InstanceList::append_block() {
  std::vector<std::size_t> order(n_instances_);
  std::iota(order.begin(), order.end(), 0);
  if (sample_instances_)
    for (std::size_t i = order.size(); i > 1; --i)
      std::swap(order[i - 1], order[rng_.below(static_cast<std::uint32_t>(i))]);
  for (std::size_t inst : order) positions_.push_back({inst, 1 + static_cast<std::uint64_t>(rng_.below(2147483647u))});
  ++blocks_;
}

void InstanceList::append(std::size_t n) {
  const std::size_t blocks = (n + n_instances_ - 1) / n_instances_;
  for (std::size_t b = 0; b < blocks; ++b) append_block();
}

InstanceList InstanceList::replay(std::size_t n_instances, std::uint64_t stream_seed, bool sample_instances,
                                  std::size_t blocks) {
  InstanceList l(n_instances, stream_seed, sample_instances);
  for (std::size_t b = 0; b < blocks; ++b) l.append_block();
  return l;
}

}  // namespace sd::design
