#pragma once
// The plain data of an ORB decomposition that its device lookup reads
// (kernels/OrbLookup.hpp); the bisection itself is host code (src/parallel/Decomposition.hpp).
namespace ondine {

// A rank's subdomain: the cells [lo, hi) of the global grid, axis by axis.
struct CellBox {
  int lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
};

// Node of the bisection tree: cells with c[axis] < cut go left. A leaf has
// axis = -1 and its rank in `left`.
struct OrbNode {
  int axis, cut, left, right;
};

}  // namespace ondine
