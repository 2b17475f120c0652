#include "app/irace_export_job.hpp"

#include "app/design_job.hpp"
#include "app/inputs.hpp"
#include "app/user_files.hpp"
#include "design/irace_export.hpp"
#include "missions/catalogue.hpp"

namespace sd::app {

std::vector<std::string> export_irace(const IraceExportRequest& request) {
  const Mission mission = load_requested_mission(request.mission);
  const design::DesignSpaceChoice choice = resolve_space(request.space);
  const design::ParameterSpace space = design::build_design_space(choice);
  // irace 3.5 refuses a budget below this minimum (computeMinimumBudget, which counts the
  // scenario's nbIterations): say so now rather than write files irace will not run.
  require_minimum_budget(request.budget, space, request.iterations);
  design::IraceScenarioSpec scenario;
  scenario.max_experiments = request.budget;
  scenario.seed = request.seed;
  scenario.digits = space.digits();
  scenario.nb_iterations = request.iterations;
  design::TargetRunnerSpec runner;
  runner.executable = request.executable;
  runner.mission = mission_reference(request.mission);
  runner.maximise = mission.objective.direction == Direction::Maximize;
  design::write_irace_files(request.out, space, scenario, {mission.name}, runner);
  return choice.notes;
}

}  // namespace sd::app
