// Orthogonal recursive bisection (src/parallel/Decomposition.hpp) on given work arrays.
#include <catch2/catch.hpp>

#include <vector>

#include "parallel/Decomposition.hpp"

using namespace ondine;

namespace {
std::vector<double> work_per_rank(const Decomposition& d, const std::vector<double>& work) {
  std::vector<double> w(d.ranks(), 0.0);
  for (int cy = 0; cy < d.cells(1); ++cy)
    for (int cx = 0; cx < d.cells(0); ++cx) {
      const int c[3] = {cx, cy, 0};
      w[d.owner(c)] += work[static_cast<std::size_t>(cy) * d.cells(0) + cx];
    }
  return w;
}
}  // namespace

TEST_CASE("ORB splits uniform work evenly and every cell has one owner", "[unit][parallel]") {
  const int n[2] = {64, 32};
  const bool periodic[2] = {false, false};
  const std::vector<double> work(64 * 32, 1.0);
  for (int ranks : {1, 2, 3, 4, 8}) {
    const Decomposition d = Decomposition::bisect(2, n, periodic, work, ranks);
    REQUIRE(d.ranks() == ranks);
    const auto w = work_per_rank(d, work);
    double total = 0;
    for (double v : w) total += v;
    CHECK(total == 64 * 32);
    // 64 x 32 cells split along whole slabs: 8 ranks get 256 cells each exactly, 3 ranks 21 or 22 columns of 32
    INFO(ranks << " ranks: tau " << balance_indicator(w) << "\n" << d.describe());
    CHECK(balance_indicator(w) >= (ranks == 3 ? 21.0 / 22.0 - 1e-12 : 1.0 - 1e-12));
  }
}

TEST_CASE("ORB weighted by work balances a dense region that equal volumes would not", "[unit][parallel]") {
  // 10x work in the left quarter (a refined or crowded region)
  const int n[2] = {80, 40};
  const bool periodic[2] = {false, false};
  std::vector<double> work(80 * 40, 1.0);
  for (int cy = 0; cy < 40; ++cy)
    for (int cx = 0; cx < 20; ++cx) work[cy * 80 + cx] = 10.0;
  const Decomposition d = Decomposition::bisect(2, n, periodic, work, 4);
  const double tau = balance_indicator(work_per_rank(d, work));
  // equal volumes (four 20-column strips): 8000 against 800 per rank, tau = 0.1.
  // ORB cuts between cells: a dense column holds 400, so a cut can miss a share
  // of 10400 / 4 = 2600 by half a column: tau >= 2400 / 2800
  INFO(d.describe());
  CHECK(tau >= 2400.0 / 2800.0 - 1e-12);
}

TEST_CASE("ORB does not cut a periodic axis of fewer than 3 cells, and says when ranks are too many", "[unit][parallel]") {
  const int n[2] = {2, 40};
  const bool periodic[2] = {true, false};
  const std::vector<double> work(80, 1.0);
  const Decomposition d = Decomposition::bisect(2, n, periodic, work, 4);
  for (int r = 0; r < 4; ++r) CHECK(d.spans(r, 0));
  const int m[2] = {3, 3};
  CHECK_THROWS_WITH(Decomposition::bisect(2, m, periodic, std::vector<double>(9, 1.0), 16),
                    Catch::Contains("cannot divide the domain among 16 ranks"));
}
