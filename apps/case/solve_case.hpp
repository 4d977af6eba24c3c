#pragma once
// The case layer's builders: a case's specs turned into the solvers' problems (nlp/) and solved.
#include <vector>

#include "case_model.hpp"
#include "normal_problem.hpp"
#include "tangential_problem.hpp"

namespace dc {

/// The whole normal case: grid, profile, operator, solve; from `warm_pressure` (one per element)
/// when given (a refined grid starting from a coarser grid's answer).
NormalSolution solve_normal_case(const ContactSpec& c, const ProgressCallback& progress = {},
                                 const std::vector<double>* warm_pressure = nullptr);

/// The gap (2.6) at each element centre: the profile's heights (profile_heights) plus
/// `worn_depth` (m per element, both bodies' worn depths summed; empty: unworn). Every solve of
/// a case takes its gap from here.
std::vector<double> contact_heights(const ContactSpec& c, const std::vector<double>& worn_depth = {});

/// The tangential problem of a case (grid, materials, profile, friction, solver.operator), set up
/// and in its unloaded state, on contact_heights(c, worn_depth). Throws InputError("friction")
/// when the case has no friction.
TangentialProblem make_tangential_problem(const ContactSpec& c, const std::vector<double>& worn_depth = {});

/// The whole tangential case (CASES.md "tangential"): one solution, or one per history step.
/// An interrupt (core/interrupt.hpp) during a history returns the steps finished before it;
/// with none finished, Interrupted propagates.
std::vector<TangentialSolution> solve_tangential_case(const Case& c, const ProgressCallback& progress = {});

}  // namespace dc
