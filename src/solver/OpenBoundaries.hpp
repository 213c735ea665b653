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
      // the facets centred on the lattice's lanes: their grid starts from the lattice origin
      // of the fluid block that fills the buffer, stepped back to cover the domain
      const FluidBlock* fill = &s.blocks.front();
      for (const FluidBlock& f : s.blocks) {
        const double lo = std::min(o.position, o.position - o.sign * o.layers * s.dx);
        if (f.box.min[o.axis] <= lo + 1e-9 * s.dx && f.box.max[o.axis] >= lo + o.layers * s.dx - 1e-9 * s.dx) {
          fill = &f;
          break;
        }
      }
      for (int k = 0; k < D; ++k) {
        if (k == o.axis) continue;
        P.t_axis[b][t] = k;
        const double origin = fill->box.min[k];
        P.t_lo[b][t] = origin - std::ceil((origin - s.domain.min[k]) / s.dx - 1e-9) * s.dx;
        P.nf[b][t] = std::max(1, static_cast<int>(std::ceil((s.domain.max[k] - P.t_lo[b][t]) / s.dx - 1e-9)));
        nf *= P.nf[b][t];
        ++t;
      }
      facets += nf;
      flux_.push_back({o.name});
    }
    facets_ = facets;
    points_ = decltype(points_)("ondine::Open::facet_points", facets);
    state_ = decltype(state_)("ondine::Open::facet_state", facets, 1 + D);
    J_mean_ = decltype(J_mean_)("ondine::Open::J_mean", facets);
    sums_ = decltype(sums_)("ondine::Open::facet_sums", facets, 2 + D);
    // per facet: <J_out>, whether it has been sampled, the last state (p, u); the sample points
    // R/2 inside the fluid from the facets' centres; before any sample, the imposed state
    host_.assign(static_cast<std::size_t>(kPerFacet * facets), 0.0);
    auto hp = Kokkos::create_mirror_view(points_);
    for (int b = 0; b < P.count; ++b) {
      const OpenBoundary& o = scene_[static_cast<std::size_t>(b)];
      const int f0 = P.facet0[b], nf = D == 2 ? P.nf[b][0] : P.nf[b][0] * P.nf[b][1];
      for (int f = 0; f < nf; ++f) {
        Vec<D> c;
        c[o.axis] = o.position + o.sign * 0.5 * s.R();
        const int c0 = D == 2 ? f : f % P.nf[b][0], c1 = D == 2 ? 0 : f / P.nf[b][0];
        c[P.t_axis[b][0]] = P.t_lo[b][0] + (c0 + 0.5) * s.dx;
        if (D == 3) c[P.t_axis[b][1]] = P.t_lo[b][1] + (c1 + 0.5) * s.dx;
        for (int k = 0; k < D; ++k) hp(f0 + f, k) = c[k];
        double* h = &host_[static_cast<std::size_t>(kPerFacet * (f0 + f))];
        const Vec<D> U = P.imposed_velocity(b, c);
        h[2] = P.pressure[b];  // an outlet's; an inlet's is the background pressure
        if (P.inlet[b]) h[2] = s.eos_background_pressure;
        for (int k = 0; k < D; ++k) h[3 + k] = P.inlet[b] ? U[k] : 0.0;
        h[0] = h[2] - s.rho0 * s.c0 * h[3 + o.axis] * o.sign;
      }
    }
    Kokkos::deep_copy(points_, hp);
    upload();
    rho0_c0_ = s.rho0 * s.c0;
    tally_ = OpenTally("ondine::Open::tally", P.count);
    // what a checkpoint must match: each boundary's kind, axis, side, plane and thickness
    for (const OpenBoundary& o : scene_)
      for (double v : {o.kind == OpenKind::Inlet ? 1.0 : 0.0, double(o.axis), double(o.sign), o.position, double(o.layers)})
        geometry_.push_back(v);
  }

  bool on() const { return planes_.count > 0; }
  const OpenPlanes<D>& planes() const { return planes_; }
  const std::vector<OpenFlux>& fluxes() const { return flux_; }
  // the sum over the boundaries (mass balances: created - removed, in - out)
  OpenFlux total() const {
    OpenFlux t{"total"};
    for (const OpenFlux& f : flux_) {
      t.mass_in += f.mass_in;
      t.mass_out += f.mass_out;
      t.created += f.created;
      t.removed += f.removed;
    }
    return t;
  }
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
    edit::Plan plan = edit::scan(action, n, open_action::remove, open_action::spawn, "ondine::Open");
    const int kept = plan.kept, ns = plan.spawned;
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
    if (p.has(field::AprParent{})) pack_family_losses(p, action, n);
    edit::order(plan, action, n, open_action::remove, open_action::spawn, 1, "ondine::Open");
    const auto all_sources =
        sorted_on_every_rank(edit::spawner_ids(plan, p.get(field::GlobalId{}), "ondine::Open"), comm, "ondine::Open::all_sources");
    const Kokkos::View<int*, MemSpace> order = plan.order;
    p.permute([&order](const auto& v) { return permuted(v, order); }, static_cast<std::size_t>(kept + ns));
    if (ns > 0)
      Kokkos::parallel_for("ondine::Open::spawn", Kokkos::RangePolicy<ExecSpace>(0, ns),
                           OpenSpawnFill<D>{planes_, kept, plan.spawners, spawn_b, all_sources, next_id, p.get(field::Position{}),
                                            p.get(field::GlobalId{}), p.get(field::OpenRole{})});
    next_id += created;
    return kept + ns;
  }

  // With refinement zones: the (mother level, mother id, -m) triples of the daughters the last
  // classify removed (OpenFamilyLosses), taken once
  std::vector<double> take_family_losses() {
    std::vector<double> taken;
    taken.swap(family_losses_);  // left empty, not merely moved from
    return taken;
  }

  // The facets' sample points, on the device (FacetSample)
  const Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace>& facet_points() const { return points_; }
  const Kokkos::View<double**, Kokkos::LayoutRight, MemSpace>& facet_sums() const { return sums_; }

  // Each facet's state from this step's sums (all ranks): p and u where the Shepard sum is 1/2
  // or more (the last state otherwise), and <J_out> filtered over the boundary's relaxation
  // time (the first sample sets it). A host loop over facets, not particles.
  void update_facets(double dt, const Communicator& comm) {
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), sums_);
    std::vector<double> v(static_cast<std::size_t>((2 + D) * facets_));
    for (int f = 0; f < facets_; ++f)
      for (int c = 0; c < 2 + D; ++c) v[static_cast<std::size_t>((2 + D) * f + c)] = h(f, c);
    comm.sum_in_place(v);
    for (int b = 0; b < planes_.count; ++b) {
      const int f0 = planes_.facet0[b], f1 = b + 1 < planes_.count ? planes_.facet0[b + 1] : facets_;
      const double a = std::min(1.0, dt / scene_[static_cast<std::size_t>(b)].relaxation_time);
      const int ax = planes_.axis[b];
      for (int f = f0; f < f1; ++f) {
        const double* sf = &v[static_cast<std::size_t>((2 + D) * f)];
        double* r = &host_[static_cast<std::size_t>(kPerFacet * f)];
        if (sf[0] < 0.5) continue;  // too little fluid at the point: the last state holds
        r[2] = sf[1] / sf[0];
        for (int k = 0; k < D; ++k) r[3 + k] = sf[2 + k] / sf[0];
        const double J = r[2] - rho0_c0_ * r[3 + ax] * planes_.sign[b];
        if (r[1] == 0) {
          r[0] = J;
          r[1] = 1;
        } else {
          r[0] += a * (J - r[0]);
        }
      }
    }
    upload();
  }

  template <class Eos>
  void apply_state(const Eos& eos, double rho0, double c0, ParticleSet<D>& p, int n) const {
    Kokkos::parallel_for("ondine::Open::buffer_state", Kokkos::RangePolicy<ExecSpace>(0, n),
                         BufferState<D, Eos>{planes_, eos, rho0, c0, p.get(field::Position{}), p.get(field::Velocity{}),
                                             p.get(field::Density{}), p.get(field::Pressure{}), p.get(field::OpenRole{}), state_,
                                             J_mean_});
  }

  // after a shifting pass into (x_out, u_out, rho_out): the buffer particles [first, end) as they were
  void keep_buffers(const ParticleSet<D>& p, int first, int end, const field_view_t<field::Position, D>& x_out,
                    const field_view_t<field::Velocity, D>& u_out, const field_view_t<field::Density, D>& rho_out) const {
    Kokkos::parallel_for("ondine::Open::keep_buffers", Kokkos::RangePolicy<ExecSpace>(first, end),
                         KeepBuffers<D>{p.get(field::OpenRole{}), p.get(field::Position{}), p.get(field::Velocity{}),
                                        p.get(field::Density{}), x_out, u_out, rho_out});
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
    c.state.insert(c.state.end(), host_.begin(), host_.end());
    c.state.insert(c.state.end(), geometry_.begin(), geometry_.end());
    return c;
  }
  // throws std::runtime_error when the state does not fit these boundaries
  void restore(const CheckpointOpen& c) {
    const std::size_t want = 5 + 4 * flux_.size() + host_.size() + geometry_.size();
    const bool same = c.present && c.state.size() == want &&
                      std::equal(geometry_.begin(), geometry_.end(), c.state.end() - static_cast<std::ptrdiff_t>(geometry_.size()));
    if (!same)
      throw std::runtime_error("the checkpoint's open boundaries (attribute open_state) are not the case's: a restart needs the "
                               "same open_boundaries (type, normal, position, layers and the domain across them)");
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
    std::copy(c.state.begin() + static_cast<std::ptrdiff_t>(k), c.state.begin() + static_cast<std::ptrdiff_t>(k + host_.size()),
              host_.begin());
    upload();
  }

 private:
  static constexpr int kPerFacet = 3 + D;  // <J_out>, sampled, p, u
  // the facets' state and <J_out> to the device
  void upload() {
    auto hs = Kokkos::create_mirror_view(state_);
    auto hj = Kokkos::create_mirror_view(J_mean_);
    for (int f = 0; f < facets_; ++f) {
      const double* r = &host_[static_cast<std::size_t>(kPerFacet * f)];
      hj(f) = r[0];
      for (int c = 0; c < 1 + D; ++c) hs(f, c) = r[2 + c];
    }
    Kokkos::deep_copy(state_, hs);
    Kokkos::deep_copy(J_mean_, hj);
  }

  std::vector<OpenBoundary> scene_;
  OpenPlanes<D> planes_;
  int facets_ = 0;
  double rho0_c0_ = 0;
  Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> points_;
  Kokkos::View<double**, Kokkos::LayoutRight, MemSpace> state_, sums_;
  Kokkos::View<double*, MemSpace> J_mean_;
  // the removed daughters' (mother level, mother id, -m), packed on the device and copied here
  void pack_family_losses(ParticleSet<D>& p, const Kokkos::View<int*, MemSpace>& action, int n) {
    OpenFamilyLosses<D> f{action, p.get(field::AprBirthLevel{}), p.get(field::AprParent{}), p.get(field::Mass{}), {}};
    int count = 0;
    Kokkos::parallel_scan("ondine::Open::family_losses_count", Kokkos::RangePolicy<ExecSpace>(0, n), f, count);
    if (count == 0) return;
    f.out = Kokkos::View<double*, MemSpace>("ondine::Open::family_losses", 3 * static_cast<std::size_t>(count));
    int again = 0;
    Kokkos::parallel_scan("ondine::Open::family_losses", Kokkos::RangePolicy<ExecSpace>(0, n), f, again);
    const auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.out);
    family_losses_.insert(family_losses_.end(), h.data(), h.data() + h.extent(0));
  }

  std::vector<double> host_, geometry_, family_losses_;
  OpenTally tally_;
  std::vector<OpenFlux> flux_;
  std::int64_t next_id_ = 0, created_count_ = 0, removed_count_ = 0;
  double initial_mass_ = 0, initial_fluid_mass_ = 0, last_dt_ = 0;
};

}  // namespace ondine
