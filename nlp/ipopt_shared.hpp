#pragma once
// What every Ipopt program of the project shares (ipopt_backend.cpp, nlp/finite/saddle_form.cpp).
#include <mutex>
#include <string>

namespace dc {

/// Ipopt's ApplicationReturnStatus as text ("Solve_Succeeded", ...).
std::string ipopt_status_name(int status);
/// Ipopt with MUMPS is not thread-safe: one Ipopt application at a time in the process. Hold
/// this lock for the application's lifetime (its linear solver included).
std::mutex& ipopt_mutex();

}  // namespace dc
