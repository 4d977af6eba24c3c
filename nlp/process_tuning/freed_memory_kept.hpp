#pragma once
// Keeps the memory the process frees in its heap for a scope (glibc), and gives it back at the
// end. MUMPS allocates its factorisation workspace afresh at every factorisation; glibc serves
// blocks above its mmap threshold (at most 32 MB) by mmap and unmaps them when freed, so every
// factorisation of the finite body's saddle form (nlp/finite/saddle_form.hpp) page-faulted and
// had the kernel zero its whole workspace again. Within this scope large blocks come from the
// heap and stay there when freed: the next factorisation reuses pages already touched.
// The settings are the process's (mallopt): scopes are counted across threads, the first sets
// them and the last restores glibc's defaults, which are the values before the first in a
// program where nothing else sets them (glibc has no way to read them back): a program opts in
// through process_tuning.hpp. Other C libraries: no effect.

namespace dc {

class FreedMemoryKept {
 public:
  FreedMemoryKept();
  ~FreedMemoryKept();  ///< the last open scope: glibc's defaults again, the kept memory trimmed
  FreedMemoryKept(const FreedMemoryKept&) = delete;
  FreedMemoryKept& operator=(const FreedMemoryKept&) = delete;
};

}  // namespace dc
