#pragma once
// The open boundaries of a run (kernels/OpenBoundary.hpp): the planes on the device, the
// facets' reference states, the next global id and the mass counters. The particle work
// is in kernels; the host loops run over boundaries and facets only.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "io/Checkpoint.hpp"
#include "kernels/FluidRegion.hpp"
#include "kernels/OpenBoundary.hpp"
#include "kernels/Permute.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/SortedIds.hpp"
#include "particles/ParticleSet.hpp"
#include "scene/Scene.hpp"

namespace ondine {

// the figures of one open boundary since t = 0 (kg)
struct OpenFlux {
  std::string name;
  double mass_in = 0, mass_out = 0;  // into and out of the fluid region across the plane
  double created = 0, removed = 0;   // particles created in, removed from, its buffer
};

template <int D>
class OpenBoundaries {
 public:
  OpenBoundaries() = default;
  OpenBoundaries(const Scene& s) : scene_(s.open_boundaries) {
    static_assert(kOpenMax == kMaxOpenBoundaries, "kernels/OpenBoundary.hpp and scene/Scene.hpp disagree");
    OpenPlanes<D>& P = planes_;
    P.count = static_cast<int>(scene_.size());
    P.dx = s.dx;
    int facets = 0;
    for (int b = 0; b < P.count; ++b) {
      const OpenBoundary& o = scene_[static_cast<std::size_t>(b)];
      P.axis[b] = o.axis;
      P.sign[b] = o.sign;
      P.position[b] = o.position;
      P.L[b] = o.layers * s.dx;
      P.inlet[b] = o.kind == OpenKind::Inlet;
      P.non_reflecting[b] = o.non_reflecting;
      for (int k = 0; k < D; ++k) P.velocity[b][k] = o.velocity[k];
      P.parabolic[b] = o.profile == InletProfile::Parabolic;
      P.profile_axis[b] = o.profile_axis;
      P.span_lo[b] = o.span_lo;
      P.span_hi[b] = o.span_hi;
      P.pressure[b] = o.pressure + s.eos_background_pressure;  // in the EOS's scale
      P.facet0[b] = facets;
      int nf = 1, t = 0;
      for (int k = 0; k < D; ++k) {
        if (k == o.axis) continue;
        P.t_axis[b][t] = k;
        P.t_lo[b][t] = s.domain.min[k];
        P.nf[b][t] = std::max(1, static_cast<int>(std::ceil((s.domain.max[k] - s.domain.min[k]) / s.dx - 1e-9)));
        nf *= P.nf[b][t];
        ++t;
      }
      facets += nf;
      flux_.push_back({o.name});
    }
    facets_ = facets;
    reference_ = decltype(reference_)("ondine::Open::reference", facets);
    facet_sums_ = decltype(facet_sums_)("ondine::Open::facet_sums", facets);
    ref_host_.assign(static_cast<std::size_t>(3 * facets), 0.0);  // p, u.n, seen
    tally_ = OpenTally("ondine::Open::tally", P.count);
  }

  bool on() const { return planes_.count > 0; }
  const OpenPlanes<D>& planes() const { return planes_; }
  const std::vector<OpenFlux>& fluxes() const { return flux_; }
  std::int64_t created_count() const { return created_count_; }
  std::int64_t removed_count() const { return removed_count_; }
  std::int64_t next_id() const { return next_id_; }
  // the total and fluid-region masses at t = 0 (for the mass balance)
  void set_initial_mass(double total, double fluid) {
    initial_mass_ = total;
    initial_fluid_mass_ = fluid;
  }
  double initial_mass() const { return initial_mass_; }
  // the last step's length: the reference states' filter at the next step start
  void set_last_dt(double dt) { last_dt_ = dt; }
  double last_dt() const { return last_dt_; }
  double initial_fluid_mass() const { return initial_fluid_mass_; }

  // a new run: roles by position, the particles beyond a buffer's outer face dropped (the
  // fluid blocks may reach past them), ids from the global count on; returns the owned count
  int start(ParticleSet<D>& p, int n, std::int64_t global_count) {
    Kokkos::View<int*, MemSpace> keep("ondine::Open::keep", n), index("ondine::Open::keep_index", n);
    Kokkos::parallel_for("ondine::Open::initial_roles", Kokkos::RangePolicy<ExecSpace>(0, n),
                         OpenInitialRoles<D>{planes_, p.get(field::Position{}), p.allocate(field::OpenRole{}), keep});
    int kept = 0;
    Kokkos::parallel_scan("ondine::Open::keep_scan", Kokkos::RangePolicy<ExecSpace>(0, n), KeepScan{keep, index}, kept);
    if (kept < n) {
      Kokkos::View<int*, MemSpace> order("ondine::Open::keep_order", kept);
      Kokkos::parallel_for("ondine::Open::keep_gather", Kokkos::RangePolicy<ExecSpace>(0, n), KeepGather{keep, index, order});
      p.permute([&order](const auto& v) { return permuted(v, order); }, static_cast<std::size_t>(kept));
    }
    next_id_ = global_count;
    return kept;
  }

  // Step start (kernels/OpenBoundary.hpp, OpenClassify): roles, particles created and removed.
  // Returns the new owned count (halos dropped where particles changed); `changed` is true on
  // every rank when particles were created or removed on any. The new ids come from
  // `id_counter` (with refinement zones, the one the APR daughters take theirs from), or from
  // the boundaries' own.
  int classify(ParticleSet<D>& p, int n, const Communicator& comm, bool& changed, std::int64_t* id_counter = nullptr) {
    std::int64_t& next_id = id_counter ? *id_counter : next_id_;
    Kokkos::View<int*, MemSpace> action("ondine::Open::action", n), spawn_b("ondine::Open::spawn_boundary", n);
    Kokkos::deep_copy(tally_, 0.0);
    Kokkos::parallel_for("ondine::Open::classify", Kokkos::RangePolicy<ExecSpace>(0, n),
                         OpenClassify<D>{planes_, p.get(field::Position{}), p.get(field::Mass{}), p.get(field::OpenRole{}), action, spawn_b,
                                         tally_});
    Kokkos::View<int*, MemSpace> kept_index("ondine::Open::kept_index", n), spawn_index("ondine::Open::spawn_index", n);
    OpenScan::value_type totals;
    Kokkos::parallel_scan("ondine::Open::scan", Kokkos::RangePolicy<ExecSpace>(0, n), OpenScan{action, kept_index, spawn_index}, totals);
    const int kept = totals.kept, ns = totals.spawned;
    {
      auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), tally_);
      std::vector<double> v(static_cast<std::size_t>(4 * planes_.count));
      for (int b = 0; b < planes_.count; ++b)
        for (int c = 0; c < 4; ++c) v[static_cast<std::size_t>(4 * b + c)] = h(b, c);
      comm.sum_in_place(v);
      for (int b = 0; b < planes_.count; ++b) {
        OpenFlux& f = flux_[static_cast<std::size_t>(b)];
        f.mass_in += v[4 * b];
        f.mass_out += v[4 * b + 1];
        f.created += v[4 * b + 2];
        f.removed += v[4 * b + 3];
      }
    }
    const std::int64_t created = comm.sum(static_cast<std::int64_t>(ns)), removed = comm.sum(static_cast<std::int64_t>(n - kept));
    created_count_ += created;
    removed_count_ += removed;
    changed = created + removed > 0;
    if (!changed) return n;
    Kokkos::View<int*, MemSpace> order("ondine::Open::order", kept + ns), boundary_of_spawn("ondine::Open::boundary_of_spawn", ns);
    Kokkos::View<std::int64_t*, MemSpace> source_id("ondine::Open::source_id", ns);
    Kokkos::parallel_for("ondine::Open::order", Kokkos::RangePolicy<ExecSpace>(0, n),
                         OpenOrder<D>{action, kept_index, spawn_index, order, boundary_of_spawn, spawn_b, source_id, p.get(field::GlobalId{}), kept});
    const auto all_sources = sorted_on_every_rank(source_id, comm, "ondine::Open::all_sources");
    p.permute([&order](const auto& v) { return permuted(v, order); }, static_cast<std::size_t>(kept + ns));
    if (ns > 0)
      Kokkos::parallel_for("ondine::Open::spawn", Kokkos::RangePolicy<ExecSpace>(0, ns),
                           OpenSpawnFill<D>{planes_, kept, boundary_of_spawn, source_id, all_sources, next_id, p.get(field::Position{}),
                                            p.get(field::GlobalId{}), p.get(field::OpenRole{})});
    next_id += created;
    return kept + ns;
  }

  // Each facet's reference state: the mean of its buffer particles' mirror samples this step,
  // filtered over the boundary's relaxation time (the first samples set it).
  void update_references(const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& sample, const ParticleSet<D>& p, int n,
                         double dt, const Communicator& comm) {
    Kokkos::deep_copy(facet_sums_, 0.0);
    Kokkos::parallel_for("ondine::Open::facet_sums", Kokkos::RangePolicy<ExecSpace>(0, n),
                         FacetSums<D>{planes_, p.get(field::Position{}), p.get(field::OpenRole{}), sample, facet_sums_});
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), facet_sums_);
    std::vector<double> v(static_cast<std::size_t>(3 * facets_));
    for (int f = 0; f < facets_; ++f)
      for (int c = 0; c < 3; ++c) v[static_cast<std::size_t>(3 * f + c)] = h(f, c);
    comm.sum_in_place(v);
    auto ref = Kokkos::create_mirror_view(reference_);
    for (int b = 0; b < planes_.count; ++b) {
      const int f0 = planes_.facet0[b], f1 = b + 1 < planes_.count ? planes_.facet0[b + 1] : facets_;
      const double a = std::min(1.0, dt / scene_[static_cast<std::size_t>(b)].relaxation_time);
      for (int f = f0; f < f1; ++f) {
        double* r = &ref_host_[static_cast<std::size_t>(3 * f)];
        const double cnt = v[3 * f + 2];
        if (cnt > 0) {
          const double pm = v[3 * f] / cnt, um = v[3 * f + 1] / cnt;
          if (r[2] == 0) {
            r[0] = pm;
            r[1] = um;
            r[2] = 1;
          } else {
            r[0] += a * (pm - r[0]);
            r[1] += a * (um - r[1]);
          }
        }
        ref(f, 0) = r[0];
        ref(f, 1) = r[1];
      }
    }
    Kokkos::deep_copy(reference_, ref);
  }

  template <class Eos>
  void apply_state(const Eos& eos, double rho0, double c0, const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& sample,
                   ParticleSet<D>& p, int n) const {
    Kokkos::parallel_for("ondine::Open::buffer_state", Kokkos::RangePolicy<ExecSpace>(0, n),
                         BufferState<D, Eos>{planes_, eos, rho0, c0, p.get(field::Position{}), p.get(field::Velocity{}),
                                             p.get(field::Density{}), p.get(field::Pressure{}), p.get(field::OpenRole{}), sample,
                                             reference_});
  }

  void zero_rates(const ParticleSet<D>& p, int n) const {
    const auto du0 = p.has(field::TransportCorrection{}) ? p.get(field::TransportCorrection{}) : field_view_t<field::TransportCorrection, D>();
    Kokkos::parallel_for("ondine::Open::zero_rates", Kokkos::RangePolicy<ExecSpace>(0, n),
                         ZeroBufferRates<D>{p.get(field::OpenRole{}), p.get(field::Acceleration{}), p.get(field::DensityRate{}), du0});
  }

  // checkpoint: next id, counts, the four masses of each boundary, the facets' references
  CheckpointOpen save() const {
    CheckpointOpen c;
    c.present = true;
    c.next_id = next_id_;
    c.state = {static_cast<double>(created_count_), static_cast<double>(removed_count_), initial_mass_, initial_fluid_mass_, last_dt_};
    for (const OpenFlux& f : flux_)
      for (double v : {f.mass_in, f.mass_out, f.created, f.removed}) c.state.push_back(v);
    c.state.insert(c.state.end(), ref_host_.begin(), ref_host_.end());
    return c;
  }
  // throws std::runtime_error when the state does not fit these boundaries
  void restore(const CheckpointOpen& c) {
    const std::size_t want = 5 + 4 * flux_.size() + ref_host_.size();
    if (!c.present || c.state.size() != want)
      throw std::runtime_error("the checkpoint's open-boundary state (attribute open_state) has " + std::to_string(c.state.size()) +
                               " values; the case's open boundaries need " + std::to_string(want) +
                               " (the open_boundaries of the case are not those of the run that wrote it)");
    next_id_ = c.next_id;
    created_count_ = static_cast<std::int64_t>(c.state[0]);
    removed_count_ = static_cast<std::int64_t>(c.state[1]);
    initial_mass_ = c.state[2];
    initial_fluid_mass_ = c.state[3];
    last_dt_ = c.state[4];
    std::size_t k = 5;
    for (OpenFlux& f : flux_) {
      f.mass_in = c.state[k++];
      f.mass_out = c.state[k++];
      f.created = c.state[k++];
      f.removed = c.state[k++];
    }
    std::copy(c.state.begin() + static_cast<std::ptrdiff_t>(k), c.state.end(), ref_host_.begin());
    auto ref = Kokkos::create_mirror_view(reference_);
    for (int f = 0; f < facets_; ++f) {
      ref(f, 0) = ref_host_[static_cast<std::size_t>(3 * f)];
      ref(f, 1) = ref_host_[static_cast<std::size_t>(3 * f + 1)];
    }
    Kokkos::deep_copy(reference_, ref);
  }

 private:
  std::vector<OpenBoundary> scene_;
  OpenPlanes<D> planes_;
  int facets_ = 0;
  Kokkos::View<double* [2], Kokkos::LayoutRight, MemSpace> reference_;
  Kokkos::View<double* [3], Kokkos::LayoutRight, MemSpace> facet_sums_;
  std::vector<double> ref_host_;
  OpenTally tally_;
  std::vector<OpenFlux> flux_;
  std::int64_t next_id_ = 0, created_count_ = 0, removed_count_ = 0;
  double initial_mass_ = 0, initial_fluid_mass_ = 0, last_dt_ = 0;
};

}  // namespace ondine
