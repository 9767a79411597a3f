// SPDX-License-Identifier: Apache-2.0
// Checks that a pipeline can work before any plugin code runs: every record
// type a stage declares it needs ("needs:<type>" in its descriptor's features)
// is produced by a stage before it. A step detector that emits STEP where the
// foot EKF needs GAIT_PHASE, or a pipeline without the attitude estimator the
// EKF needs, is refused at create instead of returning a wrong track.
#pragma once

#include <memory>
#include <vector>

#include "scheduler.hpp"

namespace pednav::engine {

// Throws ConfigProblem (PN_E_INVALID_CONFIG, where = the stage's "/plugin")
// naming the stage, the type and what the earlier stages produce.
void check_pipeline_needs(const std::vector<std::unique_ptr<Stage>>& stages);

// The record type named in descriptors and descriptions ("gait_phase"), 0 if none.
pn_record_type_t record_type_from_name(const char* name);

}  // namespace pednav::engine
