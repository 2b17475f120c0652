#pragma once
// Every JSON document of the application — what the CLI's --json prints and a web server sends
// (responses, WebSocket/SSE stream) — made in one place, src/app/documents/, one file per kind:
//   design       a design's report, live and stored progress, race log, convergence, project row,
//                Slurm job, `status` (and the stored progress read back from a cluster)
//   accounts     a project, a user's projects, the users
//   missions     the catalogue, one mission, a batch of scores
//   experiments  an experiment's plan (with its duration estimate) and the experiments' progress
//   evolution    an EvoStick evolution for a mission
//   reality      a robot model (design model or pseudo-reality sample), an assessment
// (The experiment report, control software and the module catalogue have their own makers:
// experiment_report, control_software_document.)
#include "app/documents/accounts.hpp"
#include "app/documents/design.hpp"
#include "app/documents/evolution.hpp"
#include "app/documents/experiments.hpp"
#include "app/documents/missions.hpp"
#include "app/documents/reality.hpp"
