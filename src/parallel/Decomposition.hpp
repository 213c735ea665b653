#pragma once
// Orthogonal recursive bisection (ORB) of the global cell grid, weighted by the
// work of each cell: by default its pair interactions (thesis 5.5.2, Algorithm 4),
// so that refined or denser regions balance. Every rank computes the same
// decomposition from the same (all-reduced) work array; this is a host loop over
// cells, run only when the balance indicator tau (5.30) falls below its threshold.
#include <string>
#include <vector>

#include "kernels/OrbTypes.hpp"

namespace ondine {

class Decomposition {
 public:
  Decomposition() = default;
  // The bisection of `ranks` subdomains over a grid of n[0..dim-1] cells, x
  // fastest in `work` (one value per cell). A periodic axis with fewer than 3
  // cells is never cut (a subdomain would meet the same neighbour on both sides).
  // Throws std::invalid_argument when the grid cannot hold that many subdomains.
  static Decomposition bisect(int dim, const int* n, const bool* periodic, const std::vector<double>& work, int ranks);

  int ranks() const { return static_cast<int>(boxes_.size()); }
  int dimension() const { return dim_; }
  int cells(int k) const { return n_[k]; }
  const CellBox& box(int rank) const { return boxes_[rank]; }
  bool spans(int rank, int k) const { return boxes_[rank].lo[k] == 0 && boxes_[rank].hi[k] == n_[k]; }
  const std::vector<OrbNode>& nodes() const { return nodes_; }
  int owner(const int* cell) const;  // host lookup, for tests
  std::string describe() const;      // one line per rank: its box of cells

 private:
  int build(int lo[3], int hi[3], int r0, int p, const std::vector<double>& work, const bool* periodic);
  int dim_ = 0;
  int n_[3] = {1, 1, 1};
  std::vector<CellBox> boxes_;
  std::vector<OrbNode> nodes_;
};

// tau = min_r work_r / max_r work_r (thesis 5.30): 1 is perfect balance.
double balance_indicator(const std::vector<double>& work_per_rank);

}  // namespace ondine
