#pragma once
// The documents of the reality gap: a robot model (the design model or a pseudo-reality
// sample, every knob by its file name) and an assessment (app/assess_job).
#include <nlohmann/json_fwd.hpp>

#include <string>

#include "app/assess_job.hpp"
#include "simulator/robot_model.hpp"

namespace sd::app {

nlohmann::json robot_model_document(const RobotModel& model);
nlohmann::json assessment_document(const Assessment& assessment);
/// Every run of the assessment as CSV (`assess --csv`): software, world (design or
/// pseudo-reality), sample (0 in the design model), seed, score.
std::string assessment_csv(const Assessment& assessment);

}  // namespace sd::app
