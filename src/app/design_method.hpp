#pragma once
// A design method as the application runs it — AutoMoDe's Iterated F-Race, EvoStick — behind
// one interface, so that experiments, reports and front ends never compare a method's name:
// they ask the registry (design_method(name)) and call the method.
//
//   const DesignMethod& method = design_method(condition.method);   // InvalidRequest if unknown
//   std::optional<std::string> note = method.plan(planned, condition);
//   std::optional<MadeDesign> made = method.run(planned, folder, {.threads = 2, .cancel = &token});
//   for (const auto& point : method.convergence(folder)) ...
//
// A new method: its name in design/methods.hpp, a class here (app/method_<name>.cpp) and one
// line in the registry (app/design_methods.cpp).
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/cancel_token.hpp"
#include "control/control_software.hpp"
#include "core/rng.hpp"
#include "design/methods.hpp"
#include "evaluation/evaluator.hpp"
#include "experiments/protocol.hpp"
#include "storage/design_status.hpp"
#include "storage/experiments.hpp"

namespace sd::app {

/// What a design of any method tells while it runs (on the job's thread).
class MethodObserver {
 public:
  virtual ~MethodObserver() = default;
  /// Runs used of its budget, and its best estimated score so far (the mission's units).
  virtual void progress(std::int64_t /*runs_used*/, double /*best_score*/) {}
  /// After checkpoint `step` is durable (where fault injection kills).
  virtual void checkpoint(std::int64_t /*step*/) {}
};

struct MethodRunOptions {
  unsigned threads = 0;            // 0: all cores
  Evaluator* evaluator = nullptr;  // another backend (MPI ranks); else threads
  MethodObserver* observer = nullptr;
  const CancelToken* cancel = nullptr;  // stops between two durable steps; run again to resume
};

/// A finished design.
struct MadeDesign {
  std::string control_software;  // the best, as a configuration string
  double design_score = 0.0;     // its estimated score during the design
  std::int64_t runs_used = 0;
};

class DesignMethod {
 public:
  virtual ~DesignMethod() = default;
  virtual const design::MethodInfo& info() const = 0;
  /// Completes a planned design of `condition` (its space as the database writes it) and
  /// rounds its budget to what the method can spend, with a note when it changes it.
  /// InvalidRequest for a space the catalogue cannot build.
  virtual std::optional<std::string> plan(storage::PlannedDesign& design, const experiments::Condition& condition) const = 0;
  /// Control software as the method first meets it (to measure a mission's speed).
  virtual std::vector<ControlSoftware> samples(const experiments::Condition& condition, Rng& rng) const = 0;
  /// Makes the design in `folder`, or resumes what the folder holds; nullopt when cancelled.
  virtual std::optional<MadeDesign> run(const storage::PlannedDesign& design, const std::filesystem::path& folder,
                                        const MethodRunOptions& options) const = 0;
  /// Best score against runs used, read from a finished design's folder: the one source of a
  /// design's convergence, whatever its method.
  virtual std::vector<storage::ConvergencePoint> convergence(const std::filesystem::path& folder) const = 0;
  /// The design's own document (JSON), read from its folder.
  virtual nlohmann::json document(const std::filesystem::path& folder) const = 0;
  /// How a planned design reads in a listing ("fsm / chocolate", "EvoStick").
  virtual std::string describe(const storage::PlannedDesign& design) const = 0;
  /// Whether a cluster experiment's job array can make it (false: this machine only).
  virtual bool runs_on_cluster() const = 0;
};

/// The method of that name (design/methods.hpp); InvalidRequest for a name it does not have.
const DesignMethod& design_method(std::string_view name);

/// Every design method, one line each, as the front ends list them: [{"name", "title",
/// "summary", "has_design_space"}] ("has_design_space": --method of `design` takes it).
nlohmann::json design_methods_document();

/// What a design folder holds, whichever method made it (Python's Design.open reads it):
/// {"folder", "method", and "progress", "race_log", "convergence" for Iterated F-Race, or
/// "document", "convergence" for EvoStick}. A damaged or foreign folder: DesignFolderError.
nlohmann::json design_folder_document(const std::filesystem::path& folder);

}  // namespace sd::app
