#pragma once
// Results refilled at every step of a run keep their storage: reset_keeping_storage(x) returns
// x to its default value but leaves the heap buffers of its vectors and strings (and of the
// results nested in it) in place, so that filling it again allocates nothing once it has held
// as much before.
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace dc {

template <class T>
void reset_keeping_storage(std::vector<T>& v) {
  v.clear();
}
inline void reset_keeping_storage(std::string& s) { s.clear(); }

/// `object` back to T{}, the listed members' storage kept (each reset by its own
/// reset_keeping_storage: a vector or string cleared, a nested result reset in turn).
template <class T, class... Member>
void reset_keeping_members(T& object, Member T::*... members) {
  std::tuple<Member...> kept{std::move(object.*members)...};
  object = T{};
  std::apply(
      [&](auto&... value) {
        ((reset_keeping_storage(value), object.*members = std::move(value)), ...);
      },
      kept);
}

}  // namespace dc
