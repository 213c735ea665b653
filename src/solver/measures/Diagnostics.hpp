#pragma once
// The integral diagnostics (solver/Measures.hpp).
#include <cmath>

#include "kernels/apr/LevelSums.hpp"
#include "solver/Simulation.hpp"

namespace ondine {

template <int D>
Diagnostics diagnostics(const Simulation<D>& sim) {
  const ParticleSet<D>& p = sim.particles();
  const int n_own = static_cast<int>(sim.size());
  const int n = n_own;
  const auto x = p.get(field::Position{});
  const auto u = p.get(field::Velocity{});
  const auto rho = p.get(field::Density{});
  const auto m = p.get(field::Mass{});
  Diagnostics d;
  Kokkos::parallel_reduce("ondine::Diagnostics::mass", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& s) { s += m(i); }, d.mass);
  for (int k = 0; k < D; ++k)
    Kokkos::parallel_reduce("ondine::Diagnostics::momentum", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& s) { s += m(i) * u(i, k); }, d.momentum[k]);
  Kokkos::parallel_reduce("ondine::Diagnostics::kinetic_energy", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& s) { s += 0.5 * m(i) * norm2(load<D>(u, i)); },
                          d.kinetic_energy);
  Vec<D> g;
  for (int k = 0; k < D; ++k) g[k] = sim.scene().gravity[k];
  Kokkos::parallel_reduce("ondine::Diagnostics::potential_energy", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& s) { s -= m(i) * dot(g, load<D>(x, i)); }, d.potential_energy);
  double v2 = 0;
  Kokkos::parallel_reduce("ondine::Diagnostics::max_speed", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& mx) {
                            const double s = norm2(load<D>(u, i));
                            if (s > mx) mx = s;
                          },
                          Kokkos::Max<double>(v2));
  d.max_speed = std::sqrt(v2);
  Kokkos::parallel_reduce("ondine::Diagnostics::rho_min", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& mn) { if (rho(i) < mn) mn = rho(i); },
                          Kokkos::Min<double>(d.rho_min));
  Kokkos::parallel_reduce("ondine::Diagnostics::rho_max", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, double& mx) { if (rho(i) > mx) mx = rho(i); },
                          Kokkos::Max<double>(d.rho_max));
  if (sim.refinement_on()) {
    // with refinement zones the leaves carry the fluid: a mother's mass and
    // momentum are its daughters' (passive mothers and daughter guards overlap)
    apr::LeafSum<D> f{u, m, p.get(field::AprMother{}), 0};
    d.mass = 0;
    Kokkos::parallel_reduce("ondine::Diagnostics::mass", Kokkos::RangePolicy<ExecSpace>(0, n), f, d.mass);
    for (int k = 0; k < D; ++k) {
      f.what = 1 + k;
      d.momentum[k] = 0;
      Kokkos::parallel_reduce("ondine::Diagnostics::momentum", Kokkos::RangePolicy<ExecSpace>(0, n), f, d.momentum[k]);
    }
    f.what = D + 1;
    d.kinetic_energy = 0;
    Kokkos::parallel_reduce("ondine::Diagnostics::kinetic_energy", Kokkos::RangePolicy<ExecSpace>(0, n), f, d.kinetic_energy);
    f.what = D + 2;
    f.x = x;
    f.g = g;
    d.potential_energy = 0;
    Kokkos::parallel_reduce("ondine::Diagnostics::potential_energy", Kokkos::RangePolicy<ExecSpace>(0, n), f, d.potential_energy);
  }
  // open boundaries: the fluid region's mass is the (leaf) mass less the buffers' (a buffer
  // particle is never refined); a buffer particle beyond the outer face is removed at the next
  // step start
  d.fluid_mass = d.mass;
  const bool open = p.has(field::OpenRole{});
  const auto role = open ? p.get(field::OpenRole{}) : field_view_t<field::OpenRole, D>();
  if (open) {
    double buffers = 0;
    Kokkos::parallel_reduce("ondine::Diagnostics::buffer_mass", Kokkos::RangePolicy<ExecSpace>(0, n),
                            KOKKOS_LAMBDA(const int i, double& s) { s += role(i) != 0 ? m(i) : 0.0; }, buffers);
    d.fluid_mass = d.mass - buffers;
  }
  const auto box = sim.domain().box();
  double hi[D];
  for (int k = 0; k < D; ++k) hi[k] = box.lo[k] + box.len[k];
  std::int64_t bad = 0;
  Kokkos::parallel_reduce("ondine::Diagnostics::outside_and_nan", Kokkos::RangePolicy<ExecSpace>(0, n),
                          KOKKOS_LAMBDA(const int i, std::int64_t& c) {
                            bool out = false, nan = !kmath::isfinite(rho(i));
                            for (int k = 0; k < D; ++k) {
                              nan = nan || !kmath::isfinite(x(i, k)) || !kmath::isfinite(u(i, k));
                              out = out || (!box.periodic[k] && (x(i, k) < box.lo[k] || x(i, k) > hi[k]));
                            }
                            if (role.extent(0) > 0 && role(i) != 0) out = false;
                            c += (out ? 1 : 0) + (nan ? (std::int64_t(1) << 40) : 0);
                          },
                          bad);
  // over all ranks
  d.mass = sim.comm().sum(d.mass);
  d.fluid_mass = sim.comm().sum(d.fluid_mass);
  for (int k = 0; k < D; ++k) d.momentum[k] = sim.comm().sum(d.momentum[k]);
  d.kinetic_energy = sim.comm().sum(d.kinetic_energy);
  d.potential_energy = sim.comm().sum(d.potential_energy);
  d.max_speed = sim.comm().max(d.max_speed);
  d.rho_min = sim.comm().min(d.rho_min);
  d.rho_max = sim.comm().max(d.rho_max);
  bad = sim.comm().sum(bad);
  d.outside_domain = bad & ((std::int64_t(1) << 40) - 1);
  d.finite = (bad >> 40) == 0 && std::isfinite(d.kinetic_energy);
  return d;
}

}  // namespace ondine
