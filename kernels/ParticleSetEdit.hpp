#pragma once
// An edit of the particle set, shared by the open boundaries (a particle leaves through an
// outlet, or crosses into the fluid and leaves a copy in its buffer) and refinement (a
// particle is deleted, or a mother gets 2^D daughters): each particle has an action, removed,
// kept, or kept and copied `copies` times. The edit is one exclusive scan (the survivors'
// new positions, the spawners' ranks), the gather order of the new set (the survivors in
// their order, then the copies of each spawner in the spawners' order), and the copies' new
// ids: first_id + copies (the spawner's rank among the spawners of all ranks, by id) + c,
// whatever the rank count. The caller fills the copies' fields after the gather.
#include <cstdint>
#include <string>

#include "kernels/Fields.hpp"

namespace ondine::edit {

// exclusive scans of the survivors (action != remove) and of the spawners (action == spawn)
struct Scan {
  Kokkos::View<int*, MemSpace> action, kept_index, spawn_index;
  int remove, spawn;
  struct value_type {
    int kept, spawned;
  };
  KOKKOS_INLINE_FUNCTION void init(value_type& v) const { v.kept = v.spawned = 0; }
  KOKKOS_INLINE_FUNCTION void join(volatile value_type& a, const volatile value_type& b) const {
    a.kept += b.kept;
    a.spawned += b.spawned;
  }
  KOKKOS_INLINE_FUNCTION void operator()(const int i, value_type& v, const bool final) const {
    if (final) {
      kept_index(i) = v.kept;
      spawn_index(i) = v.spawned;
    }
    v.kept += action(i) != remove ? 1 : 0;
    v.spawned += action(i) == spawn ? 1 : 0;
  }
};

// the gather order: order(kept_index(i)) = i for a survivor, order(kept + copies k + c) = i
// for the copies of the k-th spawner; spawners(k) = i
struct Order {
  Kokkos::View<int*, MemSpace> action, kept_index, spawn_index, order, spawners;
  int remove, spawn, kept, copies;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    if (action(i) == remove) return;
    order(kept_index(i)) = i;
    if (action(i) != spawn) return;
    const int k = spawn_index(i);
    spawners(k) = i;
    for (int c = 0; c < copies; ++c) order(kept + k * copies + c) = i;
  }
};

// The plan of an edit of the first n particles (Kokkos passes; the counts come back to the host)
struct Plan {
  int kept = 0, spawned = 0;
  Kokkos::View<int*, MemSpace> kept_index, spawn_index;
  Kokkos::View<int*, MemSpace> order, spawners;  // kept + copies spawned; spawned (set by order())
};

// the counts and positions (Scan): enough to learn whether the set changes
inline Plan scan(const Kokkos::View<int*, MemSpace>& action, int n, int remove, int spawn, const std::string& label) {
  Plan p;
  p.kept_index = Kokkos::View<int*, MemSpace>(label + "::kept_index", n);
  p.spawn_index = Kokkos::View<int*, MemSpace>(label + "::spawn_index", n);
  Scan::value_type totals;
  Kokkos::parallel_scan(label + "::scan", Kokkos::RangePolicy<ExecSpace>(0, n), Scan{action, p.kept_index, p.spawn_index, remove, spawn},
                        totals);
  p.kept = totals.kept;
  p.spawned = totals.spawned;
  return p;
}

// the gather order and the spawners (Order) of a scanned plan
inline void order(Plan& p, const Kokkos::View<int*, MemSpace>& action, int n, int remove, int spawn, int copies,
                  const std::string& label) {
  p.order = Kokkos::View<int*, MemSpace>(label + "::order", p.kept + copies * p.spawned);
  p.spawners = Kokkos::View<int*, MemSpace>(label + "::spawners", p.spawned);
  Kokkos::parallel_for(label + "::order", Kokkos::RangePolicy<ExecSpace>(0, n),
                       Order{action, p.kept_index, p.spawn_index, p.order, p.spawners, remove, spawn, p.kept, copies});
}

inline Plan plan(const Kokkos::View<int*, MemSpace>& action, int n, int remove, int spawn, int copies, const std::string& label) {
  Plan p = scan(action, n, remove, spawn, label);
  order(p, action, n, remove, spawn, copies, label);
  return p;
}

// the ids of the spawners, in the spawners' order (before the gather)
template <class IdView>
inline Kokkos::View<std::int64_t*, MemSpace> spawner_ids(const Plan& p, const IdView& id, const std::string& label) {
  Kokkos::View<std::int64_t*, MemSpace> ids(label + "::spawner_ids", p.spawned);
  const Kokkos::View<int*, MemSpace> spawners = p.spawners;
  Kokkos::parallel_for(label + "::spawner_ids", Kokkos::RangePolicy<ExecSpace>(0, p.spawned),
                       KOKKOS_LAMBDA(const int k) { ids(k) = id(spawners(k)); });
  return ids;
}

// the rank of `id` among the sorted ids of all ranks' spawners (binary search)
KOKKOS_INLINE_FUNCTION int rank_among(const Kokkos::View<std::int64_t*, MemSpace>& sorted, std::int64_t id) {
  int lo = 0, hi = static_cast<int>(sorted.extent(0));
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    if (sorted(mid) < id) lo = mid + 1;
    else hi = mid;
  }
  return lo;
}

// the id of copy c of a spawner whose id is `id`
KOKKOS_INLINE_FUNCTION std::int64_t copy_id(const Kokkos::View<std::int64_t*, MemSpace>& sorted, std::int64_t id, std::int64_t first_id,
                                            int copies, int c) {
  return first_id + static_cast<std::int64_t>(rank_among(sorted, id)) * copies + c;
}

}  // namespace ondine::edit
