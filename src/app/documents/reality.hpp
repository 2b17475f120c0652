#pragma once
// The documents of the reality gap: a robot model (the design model or a pseudo-reality
// sample, every knob by its file name) and an assessment (app/assess_job).
#include <nlohmann/json.hpp>

#include "app/assess_job.hpp"
#include "simulator/robot_model.hpp"

namespace sd::app {

nlohmann::json robot_model_document(const RobotModel& model);
nlohmann::json assessment_document(const Assessment& assessment);

}  // namespace sd::app
