#pragma once
// The design database as the optimiser's checkpoint store: design::CheckpointStore over
// storage::DesignStore. It lives here, the one layer that knows both, so storage keeps plain
// rows and never includes the optimiser.
#include "design/checkpoint_store.hpp"
#include "design/parameter_space.hpp"
#include "storage/design_store.hpp"

namespace sd::app {

class DesignDbCheckpoints final : public design::CheckpointStore {
 public:
  /// `space` renders each configuration's command line (for `status` and reports).
  DesignDbCheckpoints(storage::DesignStore& store, const design::ParameterSpace& space) : store_(store), space_(space) {}
  void save(const design::Checkpoint& checkpoint, std::span<const design::Elimination> eliminations) override;
  /// DesignFolderError when the stored state does not fit together.
  std::optional<design::DesignState> load() override;
  std::int64_t step() const override { return store_.step(); }

 private:
  storage::DesignStore& store_;
  const design::ParameterSpace& space_;
};

}  // namespace sd::app
