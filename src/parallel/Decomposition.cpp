#include "parallel/Decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace ondine {

Decomposition Decomposition::bisect(int dim, const int* n, const bool* periodic, const std::vector<double>& work,
                                    int ranks) {
  Decomposition d;
  d.dim_ = dim;
  std::size_t total = 1;
  for (int k = 0; k < dim; ++k) {
    d.n_[k] = n[k];
    total *= static_cast<std::size_t>(n[k]);
  }
  if (work.size() != total) throw std::logic_error("Decomposition::bisect: work array does not match the grid");
  if (ranks < 1) throw std::invalid_argument("Decomposition::bisect: at least one rank is needed");
  d.boxes_.resize(ranks);
  int lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  for (int k = 0; k < dim; ++k) hi[k] = n[k];
  d.build(lo, hi, 0, ranks, work, periodic);
  return d;
}

int Decomposition::build(int lo[3], int hi[3], int r0, int p, const std::vector<double>& work, const bool* periodic) {
  const int self = static_cast<int>(nodes_.size());
  nodes_.push_back({-1, 0, r0, r0});
  if (p == 1) {
    for (int k = 0; k < 3; ++k) {
      boxes_[r0].lo[k] = lo[k];
      boxes_[r0].hi[k] = hi[k];
    }
    return self;
  }
  // the longest axis that can be cut
  int axis = -1;
  for (int k = 0; k < dim_; ++k) {
    const bool cuttable = hi[k] - lo[k] >= 2 && (!periodic[k] || n_[k] >= 3);
    if (cuttable && (axis < 0 || hi[k] - lo[k] > hi[axis] - lo[axis])) axis = k;
  }
  if (axis < 0) {
    std::ostringstream m;
    m << "cannot divide the domain among " << boxes_.size() << " ranks: a subdomain of";
    for (int k = 0; k < dim_; ++k) m << " " << hi[k] - lo[k];
    m << " cells (cells are R + skin wide) would have to hold " << p << " ranks; use fewer ranks or a finer case";
    throw std::invalid_argument(m.str());
  }
  // work per slab along the axis, inside this box
  std::vector<double> slab(hi[axis] - lo[axis], 0.0);
  int c[3];
  for (c[2] = lo[2]; c[2] < hi[2]; ++c[2])
    for (c[1] = lo[1]; c[1] < hi[1]; ++c[1])
      for (c[0] = lo[0]; c[0] < hi[0]; ++c[0]) {
        const std::size_t idx = (static_cast<std::size_t>(c[2]) * n_[1] + c[1]) * n_[0] + c[0];
        slab[c[axis] - lo[axis]] += work[idx];
      }
  double total = 0;
  for (double s : slab) total += s;
  const int p_left = p / 2;
  // cut where the work on the left is closest to p_left / p of the total (by
  // geometry when the box has no work); both sides keep at least one cell
  int cut = lo[axis] + static_cast<int>(std::lround(static_cast<double>(hi[axis] - lo[axis]) * p_left / p));
  if (total > 0) {
    const double target = total * p_left / p;
    double cum = 0, best = 1e300;
    for (int k = lo[axis] + 1; k < hi[axis]; ++k) {
      cum += slab[k - 1 - lo[axis]];
      if (std::abs(cum - target) < best) {
        best = std::abs(cum - target);
        cut = k;
      }
    }
  }
  cut = std::min(std::max(cut, lo[axis] + 1), hi[axis] - 1);
  int lhi[3] = {hi[0], hi[1], hi[2]}, rlo[3] = {lo[0], lo[1], lo[2]};
  lhi[axis] = cut;
  rlo[axis] = cut;
  const int left = build(lo, lhi, r0, p_left, work, periodic);
  const int right = build(rlo, hi, r0 + p_left, p - p_left, work, periodic);
  nodes_[self] = {axis, cut, left, right};
  return self;
}

int Decomposition::owner(const int* cell) const {
  if (nodes_.empty()) return 0;
  int node = 0;
  while (nodes_[node].axis >= 0) node = cell[nodes_[node].axis] < nodes_[node].cut ? nodes_[node].left : nodes_[node].right;
  return nodes_[node].left;
}

std::string Decomposition::describe() const {
  std::ostringstream m;
  for (int r = 0; r < ranks(); ++r) {
    m << "rank " << r << ": cells";
    for (int k = 0; k < dim_; ++k) m << " [" << boxes_[r].lo[k] << "," << boxes_[r].hi[k] << ")";
    m << "\n";
  }
  return m.str();
}

double balance_indicator(const std::vector<double>& w) {
  if (w.empty()) return 1.0;
  const auto [mn, mx] = std::minmax_element(w.begin(), w.end());
  return *mx > 0 ? *mn / *mx : 1.0;
}

}  // namespace ondine
