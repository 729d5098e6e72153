/// @file revisit_fit.h
/// @brief Whether the planned revisits fit in the simulated frames, and how many frames would hold them all.
#pragma once

#include "sgtllc/sim/simulator.h"

namespace sgtllc::sim {

/// Revisits the simulated frames drive: runs of consecutive frames of one revisit kind (route.h isRevisit).
int drivenRevisits(const Simulator& simulator);

/// The smallest tried frame count (from an estimate, growing by a tenth) whose route drives all of
/// @p config.plannedRevisits(); 0 if none of 16 tries does. Plans routes only, renders nothing.
int framesForRevisits(const SimConfig& config);

}  // namespace sgtllc::sim
