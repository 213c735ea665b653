// Cell list + CSR neighbour list against an O(N^2) brute-force oracle on the
// host: identical neighbour sets, 2D and 3D, periodic and not, random and lattice.
#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <vector>

#include "kernels/NeighbourList.hpp"

using namespace ondine;

namespace {

template <int D>
void compare_with_brute_force(const std::vector<std::array<double, 3>>& pts, const PeriodicBox<D>& box, double cutoff) {
  const int n = static_cast<int>(pts.size());
  field_view_t<field::Position, D> x("x", n);
  auto hx = Kokkos::create_mirror_view(x);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < D; ++k) hx(i, k) = pts[i][k];
  Kokkos::deep_copy(x, hx);

  CellList<D> cells;
  cells.build(make_cell_grid(box, cutoff), x, n);
  NeighbourList<D> list;
  list.build(cells, box, x, n, cutoff);

  auto off = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.offsets);
  auto nb = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), list.neighbours);
  long total = 0;
  int mismatches = 0;
  for (int i = 0; i < n; ++i) {
    std::vector<int> expect;
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      double r2 = 0;
      for (int k = 0; k < D; ++k) {
        double d = pts[i][k] - pts[j][k];
        if (box.periodic[k]) d -= box.len[k] * std::round(d / box.len[k]);
        r2 += d * d;
      }
      if (r2 < cutoff * cutoff) expect.push_back(j);
    }
    std::vector<int> got(nb.data() + off(i), nb.data() + off(i + 1));
    std::sort(got.begin(), got.end());
    total += static_cast<long>(expect.size());
    if (got != expect) ++mismatches;
  }
  CHECK(mismatches == 0);
  CHECK(off(n) == total);
  CHECK(total > 0);
}

template <int D>
PeriodicBox<D> make_box(const std::array<double, 3>& len, bool periodic) {
  PeriodicBox<D> b;
  for (int k = 0; k < D; ++k) {
    b.lo[k] = -0.3;
    b.len[k] = len[k];
    b.periodic[k] = periodic && k != 1;  // mixed: y stays open
  }
  return b;
}

template <int D>
void run_all(int n_random) {
  std::mt19937 rng(1234 + D);
  for (bool periodic : {false, true}) {
    const std::array<double, 3> len{1.0, 0.7, 0.45};
    const PeriodicBox<D> box = make_box<D>(len, periodic);
    // random points, a few outside the open axis to exercise clamped cells
    std::vector<std::array<double, 3>> pts(n_random);
    for (auto& p : pts)
      for (int k = 0; k < D; ++k) {
        std::uniform_real_distribution<double> u(box.lo[k] - (box.periodic[k] ? 0 : 0.05), box.lo[k] + len[k] + (box.periodic[k] ? 0 : 0.05));
        p[k] = u(rng);
        if (box.periodic[k] && p[k] >= box.lo[k] + len[k]) p[k] = box.lo[k];
      }
    for (double cutoff : {0.061, 0.13, 0.2}) compare_with_brute_force<D>(pts, box, cutoff);
    // lattice with spacing dx: neighbours exactly at distances k dx, cut-off between shells
    const double dx = D == 2 ? 0.025 : 0.05;
    std::vector<std::array<double, 3>> lat;
    int cnt[3] = {1, 1, 1};
    for (int k = 0; k < D; ++k) cnt[k] = static_cast<int>(std::round(len[k] / dx));
    for (int a = 0; a < cnt[0]; ++a)
      for (int b = 0; b < cnt[1]; ++b)
        for (int c = 0; c < cnt[2]; ++c) lat.push_back({box.lo[0] + (a + 0.5) * dx, box.lo[1] + (b + 0.5) * dx, D == 3 ? box.lo[2] + (c + 0.5) * dx : 0.0});
    compare_with_brute_force<D>(lat, box, 3.0001 * dx);
    compare_with_brute_force<D>(lat, box, 2.5 * dx);
  }
}

}  // namespace

TEST_CASE("Neighbour list equals brute force in 2D", "[unit][neighbours]") { run_all<2>(1500); }
TEST_CASE("Neighbour list equals brute force in 3D", "[unit][neighbours]") { run_all<3>(2000); }

TEST_CASE("A periodic axis shorter than 3 cells still finds each neighbour once", "[unit][neighbours]") {
  PeriodicBox<2> box;
  box.lo[0] = box.lo[1] = 0;
  box.len[0] = 0.25;  // 2 cells of 0.125 with cutoff 0.12
  box.len[1] = 1.0;
  box.periodic[0] = box.periodic[1] = true;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> ux(0, 0.25), uy(0, 1.0);
  std::vector<std::array<double, 3>> pts(300);
  for (auto& p : pts) p = {ux(rng), uy(rng), 0};
  compare_with_brute_force<2>(pts, box, 0.12);
}
