#pragma once
// Moves particles between ranks (header-only: instantiated by Simulation<D>).
//  - migrate(): after a neighbour-list interval, every owned particle goes to
//    the owner of its cell, with all its allocated fields and its global id;
//  - build_halos(): copies of the owned particles that lie in another rank's
//    ring of halo cells, at the periodic image that rank sees, stored after the
//    owned particles (indices n_own ..);
//  - refresh(tags...): new values of the given fields for the same halos, before
//    each pass that reads neighbours (RK substages included).
// Packing and unpacking run on the device; MPI moves host copies of the buffers.
#include <Kokkos_Core.hpp>
#include <Kokkos_Sort.hpp>
#include <Kokkos_Timer.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "kernels/FluidRegion.hpp"
#include "kernels/OrbLookup.hpp"
#include "kernels/PeriodicBox.hpp"
#include "parallel/Communicator.hpp"
#include "particles/ParticleSet.hpp"

namespace ondine {

namespace exchange {

using Rows = Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>;

// doubles per particle of a field view (1, or its static second extent), as a
// compile-time constant usable in device code
template <class V, bool Scalar = (V::rank == 1)>
struct RowWidth {
  static constexpr int value = 1;
};
template <class V>
struct RowWidth<V, false> {
  static constexpr int value = static_cast<int>(V::static_extent(1));
};
template <class V>
constexpr int width_of() {
  return RowWidth<V>::value;
}

// rows(e, col ..) = v(index(e)), positions shifted to the image `code(e)` when given
template <class V, int D>
struct PackRows {
  V v;
  Kokkos::View<int*, MemSpace> index, code;  // code empty: no shift
  Rows rows;
  int col;
  double len[D];
  KOKKOS_INLINE_FUNCTION void operator()(const int e) const {
    const int i = index(e);
    if constexpr (V::rank == 1) {
      rows(e, col) = static_cast<double>(v(i));
    } else {
      for (int k = 0; k < RowWidth<V>::value; ++k)
        rows(e, col + k) = v(i, k) + (code.extent(0) > 0 ? image_shift(code(e), k) * len[k] : 0.0);
    }
  }
};

// v(first + e) = rows(e, col ..)
template <class V>
struct UnpackRows {
  V v;
  Rows rows;
  int col, first;
  KOKKOS_INLINE_FUNCTION void operator()(const int e) const {
    if constexpr (V::rank == 1) {
      v(first + e) = static_cast<typename V::value_type>(rows(e, col));
    } else {
      for (int k = 0; k < RowWidth<V>::value; ++k) v(first + e, k) = rows(e, col + k);
    }
  }
};

// out(i) = in(order(i))
template <class V>
struct GatherRows {
  V in, out;
  Kokkos::View<int*, MemSpace> order;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    if constexpr (V::rank == 1) out(i) = in(order(i));
    else
      for (int k = 0; k < RowWidth<V>::value; ++k) out(i, k) = in(order(i), k);
  }
};

// Wraps positions into the periodic box; the RK stage start x0 (if any) moves by the same shift.
template <int D>
struct WrapOwned {
  PeriodicBox<D> box;
  field_view_t<field::Position, D> x, x0;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    for (int k = 0; k < D; ++k) {
      const double w = box.wrap(x(i, k), k);
      if (x0.extent(0) > 0) x0(i, k) += w - x(i, k);
      x(i, k) = w;
    }
  }
};

template <int D>
struct OwnerOf {
  OrbLookup<D> orb;
  field_view_t<field::Position, D> x;
  Kokkos::View<int*, MemSpace> dest, keep;
  int me;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    dest(i) = orb.owner(load<D>(x, i));
    keep(i) = dest(i) == me ? 1 : 0;
  }
};

// key = dest * n + i for the particles that leave (sorted keys: by rank, then index)
struct LeaveKeys {
  Kokkos::View<int*, MemSpace> dest, keep, index;
  Kokkos::View<std::int64_t*, MemSpace> keys;
  std::int64_t n;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    if (!keep(i)) keys(i - index(i)) = dest(i) * n + i;  // index(i) = kept before i
  }
};

template <int D>
struct HaloCount {
  OrbLookup<D> orb;
  field_view_t<field::Position, D> x;
  Kokkos::View<int*, MemSpace> count;
  int me;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    int c = 0;
    orb.for_each_halo_destination(me, load<D>(x, i), [&](int, int) { ++c; });
    count(i) = c;
  }
};

struct ExclusiveScan {
  Kokkos::View<int*, MemSpace> count, offset;
  KOKKOS_INLINE_FUNCTION void operator()(const int i, int& partial, const bool final) const {
    if (final) offset(i) = partial;
    partial += count(i);
  }
};

// key = (dest * n + i) * image_codes + image
template <int D>
struct HaloKeys {
  OrbLookup<D> orb;
  field_view_t<field::Position, D> x;
  Kokkos::View<int*, MemSpace> offset;
  Kokkos::View<std::int64_t*, MemSpace> keys;
  std::int64_t n;
  int me;
  KOKKOS_INLINE_FUNCTION void operator()(const int i) const {
    int p = offset(i);
    orb.for_each_halo_destination(me, load<D>(x, i), [&](int r, int code) { keys(p++) = (r * n + i) * image_codes + code; });
  }
};

struct DecodeKeys {
  Kokkos::View<std::int64_t*, MemSpace> keys;
  Kokkos::View<int*, MemSpace> index, code, per_rank;
  std::int64_t n;
  bool with_code;
  KOKKOS_INLINE_FUNCTION void operator()(const int e) const {
    std::int64_t k = keys(e);
    if (with_code) {
      code(e) = static_cast<int>(k % image_codes);
      k /= image_codes;
    }
    index(e) = static_cast<int>(k % n);
    Kokkos::atomic_increment(&per_rank(static_cast<int>(k / n)));
  }
};

inline void sort_keys(const Kokkos::View<std::int64_t*, MemSpace>& keys) {
  if (keys.extent(0) > 1) Kokkos::sort(keys);
}

inline std::vector<int> to_host_vector(const Kokkos::View<int*, MemSpace>& v) {
  std::vector<int> out(v.extent(0));
  Kokkos::deep_copy(Kokkos::View<int*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(out.data(), out.size()), v);
  return out;
}

}  // namespace exchange

template <int D>
class ParticleExchange {
 public:
  // Sends every owned particle whose cell another rank owns to that rank (all
  // allocated fields; halos are dropped); returns the new owned count.
  int migrate(ParticleSet<D>& p, int n_own, const OrbLookup<D>& orb, const PeriodicBox<D>& box, const Communicator& comm) {
    using namespace exchange;
    Kokkos::Timer timer;
    const auto x = p.get(field::Position{});
    const auto x0 = p.has(field::StagePosition{}) ? p.get(field::StagePosition{}) : field_view_t<field::Position, D>();
    Kokkos::parallel_for("ondine::Migrate::wrap", Kokkos::RangePolicy<ExecSpace>(0, n_own), WrapOwned<D>{box, x, x0});
    Kokkos::View<int*, MemSpace> dest("ondine::Migrate::dest", n_own), keep("ondine::Migrate::keep", n_own),
        index("ondine::Migrate::index", n_own);
    Kokkos::parallel_for("ondine::Migrate::owner", Kokkos::RangePolicy<ExecSpace>(0, n_own), OwnerOf<D>{orb, x, dest, keep, comm.rank()});
    int kept = 0;
    Kokkos::parallel_scan("ondine::Migrate::scan", Kokkos::RangePolicy<ExecSpace>(0, n_own), KeepScan{keep, index}, kept);
    Kokkos::View<int*, MemSpace> order("ondine::Migrate::order", kept);
    Kokkos::parallel_for("ondine::Migrate::gather", Kokkos::RangePolicy<ExecSpace>(0, n_own), KeepGather{keep, index, order});
    const int leaving = n_own - kept;
    Kokkos::View<std::int64_t*, MemSpace> keys("ondine::Migrate::keys", leaving);
    Kokkos::parallel_for("ondine::Migrate::keys", Kokkos::RangePolicy<ExecSpace>(0, n_own), LeaveKeys{dest, keep, index, keys, n_own});
    sort_keys(keys);
    Kokkos::View<int*, MemSpace> send_index("ondine::Migrate::send_index", leaving), per_rank("ondine::Migrate::per_rank", comm.size());
    Kokkos::parallel_for("ondine::Migrate::decode", Kokkos::RangePolicy<ExecSpace>(0, leaving),
                         DecodeKeys{keys, send_index, Kokkos::View<int*, MemSpace>(), per_rank, n_own, false});
    const std::vector<int> send_counts = to_host_vector(per_rank);
    const std::vector<int> recv_counts = comm.exchange_counts(send_counts);
    int received = 0;
    for (int c : recv_counts) received += c;
    int width = 0;
    p.for_each_allocated([&](auto, const auto& v) { width += width_of<std::decay_t<decltype(v)>>(); });
    Rows out("ondine::Migrate::send", leaving, width), in("ondine::Migrate::recv", received, width);
    int col = 0;
    p.for_each_allocated([&](auto, const auto& v) {
      using V = std::decay_t<decltype(v)>;
      PackRows<V, D> f{v, send_index, Kokkos::View<int*, MemSpace>(), out, col, {}};
      Kokkos::parallel_for("ondine::Migrate::pack", Kokkos::RangePolicy<ExecSpace>(0, leaving), f);
      col += width_of<V>();
    });
    move_rows(out, send_counts, in, recv_counts, width, comm);
    col = 0;
    p.permute(
        [&](const auto& v) {
          using V = std::decay_t<decltype(v)>;
          V w(v.label(), kept + received);
          Kokkos::parallel_for("ondine::Migrate::keep", Kokkos::RangePolicy<ExecSpace>(0, kept), GatherRows<V>{v, w, order});
          Kokkos::parallel_for("ondine::Migrate::unpack", Kokkos::RangePolicy<ExecSpace>(0, received), UnpackRows<V>{w, in, col, kept});
          col += width_of<V>();
          return w;
        },
        static_cast<std::size_t>(kept + received));
    migrated_ += comm.sum(static_cast<std::int64_t>(leaving));
    migration_seconds_ += timer.seconds();
    return kept + received;
  }

  // Copies of owned particles for the ranks whose halo ring holds them, stored
  // after the owned ones (p resized to n_own + halos): position (at the image the
  // receiver sees), velocity, density, mass and global id.
  void build_halos(ParticleSet<D>& p, int n_own, const OrbLookup<D>& orb, const PeriodicBox<D>& box, const Communicator& comm) {
    using namespace exchange;
    Kokkos::Timer timer;
    n_own_ = n_own;
    for (int k = 0; k < D; ++k) len_[k] = box.len[k];
    const auto x = p.get(field::Position{});
    Kokkos::View<int*, MemSpace> count("ondine::Halo::count", n_own), offset("ondine::Halo::offset", n_own);
    Kokkos::parallel_for("ondine::Halo::count", Kokkos::RangePolicy<ExecSpace>(0, n_own), HaloCount<D>{orb, x, count, comm.rank()});
    int total = 0;
    Kokkos::parallel_scan("ondine::Halo::scan", Kokkos::RangePolicy<ExecSpace>(0, n_own), ExclusiveScan{count, offset}, total);
    Kokkos::View<std::int64_t*, MemSpace> keys("ondine::Halo::keys", total);
    Kokkos::parallel_for("ondine::Halo::keys", Kokkos::RangePolicy<ExecSpace>(0, n_own),
                         HaloKeys<D>{orb, x, offset, keys, std::max<std::int64_t>(n_own, 1), comm.rank()});
    sort_keys(keys);
    send_index_ = Kokkos::View<int*, MemSpace>("ondine::Halo::send_index", total);
    send_code_ = Kokkos::View<int*, MemSpace>("ondine::Halo::send_image", total);
    Kokkos::View<int*, MemSpace> per_rank("ondine::Halo::per_rank", comm.size());
    Kokkos::parallel_for("ondine::Halo::decode", Kokkos::RangePolicy<ExecSpace>(0, total),
                         DecodeKeys{keys, send_index_, send_code_, per_rank, std::max<std::int64_t>(n_own, 1), true});
    send_counts_ = to_host_vector(per_rank);
    recv_counts_ = comm.exchange_counts(send_counts_);
    n_halo_ = 0;
    for (int c : recv_counts_) n_halo_ += c;
    p.resize(static_cast<std::size_t>(n_own + n_halo_));
    refresh(p, comm, field::Position{}, field::Velocity{}, field::Density{}, field::Mass{}, field::GlobalId{});
    halo_seconds_ += timer.seconds();
  }

  // New values of the given fields in every halo copy.
  template <class... Tags>
  void refresh(ParticleSet<D>& p, const Communicator& comm, Tags... tags) {
    using namespace exchange;
    Kokkos::Timer timer;
    const int total = static_cast<int>(send_index_.extent(0));
    const int width = (width_of<field_view_t<Tags, D>>() + ...);
    Buffers& b = buffers(width, total, n_halo_);
    const Rows out = b.out, in = b.in;
    int col = 0;
    auto pack = [&](auto tag) {
      using V = field_view_t<decltype(tag), D>;
      PackRows<V, D> f{p.get(tag), send_index_,
                       std::is_same<decltype(tag), field::Position>::value ? send_code_ : Kokkos::View<int*, MemSpace>(), out, col, {}};
      for (int k = 0; k < D; ++k) f.len[k] = len_[k];
      Kokkos::parallel_for("ondine::Halo::pack", Kokkos::RangePolicy<ExecSpace>(0, total), f);
      col += width_of<V>();
    };
    (pack(tags), ...);
    Kokkos::deep_copy(b.h_out, out);
    comm.exchange_known(b.h_out.data(), send_counts_, b.h_in.data(), recv_counts_, width);
    Kokkos::deep_copy(in, b.h_in);
    col = 0;
    auto unpack = [&](auto tag) {
      using V = field_view_t<decltype(tag), D>;
      Kokkos::parallel_for("ondine::Halo::unpack", Kokkos::RangePolicy<ExecSpace>(0, n_halo_), UnpackRows<V>{p.get(tag), in, col, n_own_});
      col += width_of<V>();
    };
    (unpack(tags), ...);
    halo_seconds_ += timer.seconds();
  }

  int halo_count() const { return n_halo_; }
  std::int64_t migrated() const { return migrated_; }  // particles moved between ranks, all ranks, so far
  double seconds() const { return migration_seconds_ + halo_seconds_; }  // wall time in migration and halo exchange
  double migration_seconds() const { return migration_seconds_; }
  double halo_seconds() const { return halo_seconds_; }  // halo builds and refreshes

 private:
  // send and receive buffers of the halo refreshes, by row width, kept between calls
  struct Buffers {
    exchange::Rows out, in;
    exchange::Rows::HostMirror h_out, h_in;
  };
  Buffers& buffers(int width, int n_out, int n_in) {
    Buffers& b = buffers_[width];
    auto fit = [width](exchange::Rows& v, exchange::Rows::HostMirror& h, int n, const char* label) {
      if (static_cast<int>(v.extent(0)) == n && v.is_allocated()) return;
      v = exchange::Rows(Kokkos::view_alloc(Kokkos::WithoutInitializing, std::string(label)), n, width);
      h = Kokkos::create_mirror_view(v);
    };
    fit(b.out, b.h_out, n_out, "ondine::Halo::send");
    fit(b.in, b.h_in, n_in, "ondine::Halo::recv");
    return b;
  }
  std::map<int, Buffers> buffers_;

  static void move_rows(const exchange::Rows& out, const std::vector<int>& send_counts, const exchange::Rows& in,
                        const std::vector<int>& recv_counts, int width, const Communicator& comm) {
    auto h_out = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), out);
    auto h_in = Kokkos::create_mirror_view(in);
    comm.exchange_known(h_out.data(), send_counts, h_in.data(), recv_counts, width);
    Kokkos::deep_copy(in, h_in);
  }

  Kokkos::View<int*, MemSpace> send_index_, send_code_;
  std::vector<int> send_counts_, recv_counts_;
  int n_own_ = 0, n_halo_ = 0;
  double len_[D] = {};
  std::int64_t migrated_ = 0;
  double migration_seconds_ = 0, halo_seconds_ = 0;
};

}  // namespace ondine
