#pragma once
// Definitions of Simulation<D>, one file per part; included by Simulation2d.cpp and
// Simulation3d.cpp only.
#include "solver/SimulationSetup.hpp"
#include "solver/SimulationLists.hpp"
#include "solver/SimulationEvaluate.hpp"
#include "solver/SimulationStep.hpp"
#include "solver/SimulationLocalSteps.hpp"
#include "solver/SimulationOutput.hpp"
