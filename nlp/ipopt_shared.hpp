#pragma once
// What every Ipopt program of the project shares (ipopt_backend.cpp, nlp/finite/saddle_form.cpp,
// shakedown_problem.cpp).
#include <mutex>
#include <string>

namespace Ipopt {
class OptionsList;
}

namespace dc {

/// The options every program here sets alike: the tolerance, the iteration limit, the output
/// (print level 5 when verbose, else silent and without Ipopt's banner). False when Ipopt
/// rejected one.
bool set_common_ipopt_options(Ipopt::OptionsList& options, double tol, int max_iter, bool verbose);

/// Ipopt's ApplicationReturnStatus as text ("Solve_Succeeded", ...).
std::string ipopt_status_name(int status);
/// Ipopt with MUMPS is not thread-safe: one Ipopt application at a time in the process. Hold
/// this lock for the application's lifetime (its linear solver included).
std::mutex& ipopt_mutex();

}  // namespace dc
