#pragma once
// The validation cases of `ondine validate`: each case's file, reference length, ladder,
// bounds and overrides (docs/validation.md), and the group a case belongs to.
#include <string>
#include <vector>

#include "app/ValidateReport.hpp"

namespace ondine::validate {

// every case, in the order validate runs them
const std::vector<ValidationCase>& catalogue();

// stability (the stability suite), apr (the APR comparisons), open (open boundaries), fine
// (SPHERIC Test 2 at fine resolution), turbulence (the turbulence models), impact (the wedge
// against its similarity solution) or accuracy (the
// accuracy ladders, what validate runs without --case)
std::string group_of(const std::string& name);

}  // namespace ondine::validate
