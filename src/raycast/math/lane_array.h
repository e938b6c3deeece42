#pragma once
// N values of T, one per packet lane, left uninitialised: Ray, LocalHit and the like zero
// themselves by their default member initialisers, which for arrays of sixteen rays cost more
// per packet than the lanes' own work (rep stos of 1 KB). For packet code that writes each lane
// before it reads it. T must be trivially destructible.
#include <type_traits>

namespace raycast {

template <class T, int N>
struct LaneArray {
  static_assert(std::is_trivially_destructible_v<T>);
  union {
    T lane[N];
  };
  LaneArray() {}  // no member initialised (user-provided, so the lanes stay as they are)
  T& operator[](int l) { return lane[l]; }
  const T& operator[](int l) const { return lane[l]; }
  T* data() { return lane; }
  const T* data() const { return lane; }
};

}  // namespace raycast
