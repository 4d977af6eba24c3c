#pragma once
// Hooks around an Ipopt application on a sparse block (the finite body's saddle form,
// nlp/finite/saddle_form.hpp), where MUMPS factorises a large KKT matrix. The library installs
// none and changes nothing in the process; a program may install process-wide tuning here
// (nlp/process_tuning/process_tuning.hpp: MUMPS ordered by METIS, freed memory kept), as
// `dyncontact` and the Python module do.

namespace dc {

struct SparseFactorisationHooks {
  void (*enter)() = nullptr;  ///< before the application is created
  void (*leave)() = nullptr;  ///< after it is gone (the one that was installed at enter)
};

/// Installs `hooks` for the whole process (both nullptr: none).
void set_sparse_factorisation_hooks(const SparseFactorisationHooks& hooks);

/// The installed hooks' scope: enter() at construction, leave() at destruction.
class SparseFactorisationScope {
 public:
  SparseFactorisationScope();
  ~SparseFactorisationScope();
  SparseFactorisationScope(const SparseFactorisationScope&) = delete;
  SparseFactorisationScope& operator=(const SparseFactorisationScope&) = delete;

 private:
  void (*leave_)() = nullptr;
};

}  // namespace dc
