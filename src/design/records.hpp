#pragma once
// The plain records a design process accumulates (irace: allConfigurations, experimentLog,
// elites with their selection weights).
#include <cstddef>
#include <vector>

#include "design/parameter_space.hpp"

namespace sd::design {

struct ConfigRecord {
  int id = 0;      // 1-based, equals index + 1 in the store
  int parent = 0;  // elite it was sampled from; 0 for uniform / initial configurations
  Configuration config;
};

struct ExperimentRecord {
  int iteration = 0;
  std::size_t position = 0;  // 1-based position in the instance list
  int configuration_id = 0;
  double cost = 0.0;
};

struct Elite {
  int id = 0;
  double weight = 0.0;  // probability of being picked as a parent: (N - r + 1) / (N (N + 1) / 2)
};

/// All configurations ever sampled, addressed by id.
class ConfigurationStore {
 public:
  const ConfigRecord& operator[](int id) const { return records_.at(static_cast<std::size_t>(id - 1)); }
  int add(Configuration c, int parent) {
    const int id = static_cast<int>(records_.size()) + 1;
    records_.push_back({id, parent, std::move(c)});
    return id;
  }
  int next_id() const { return static_cast<int>(records_.size()) + 1; }
  std::size_t size() const { return records_.size(); }
  const std::vector<ConfigRecord>& all() const { return records_; }
  std::vector<ConfigRecord>& all() { return records_; }

 private:
  std::vector<ConfigRecord> records_;
};

}  // namespace sd::design
