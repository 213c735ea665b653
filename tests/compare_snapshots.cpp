// ondine_compare A.h5 B.h5 TOL [FIELD ...]: matches the particles of two snapshots
// by global id and prints, per field, the largest difference relative to the
// field's largest magnitude in A; exits 1 if any exceeds TOL (0: bitwise), or if
// the particle sets differ. Default fields: position, velocity, density, pressure;
// `all`: every dataset of A but the id (and B must have the same datasets).
// Checkpoints (OUT/checkpoint.h5) are read as well.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <numeric>
#include <string>
#include <vector>

#include "io/SnapshotWriter.hpp"

using ondine::SnapshotData;

static const std::vector<double>* field(const SnapshotData& d, const std::string& name, int& comps) {
  for (std::size_t k = 0; k < d.names.size(); ++k)
    if (d.names[k] == name) {
      comps = d.components[k];
      return &d.values[k];
    }
  return nullptr;
}

static std::vector<std::size_t> by_id(const SnapshotData& d) {
  int c = 1;
  const auto* id = field(d, "id", c);
  std::vector<std::size_t> order(d.particles);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return (*id)[a] < (*id)[b]; });
  return order;
}

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: ondine_compare A.h5 B.h5 TOL [FIELD ...]\n");
    return 2;
  }
  SnapshotData a, b;
  try {
    a = ondine::read_snapshot(argv[1]);
    b = ondine::read_snapshot(argv[2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ondine_compare: %s\n", e.what());
    return 2;
  }
  const double tol = std::atof(argv[3]);
  std::vector<std::string> names;
  for (int k = 4; k < argc; ++k) names.emplace_back(argv[k]);
  if (names.empty()) names = {"position", "velocity", "density", "pressure"};
  if (names.size() == 1 && names[0] == "all") {
    names.clear();
    for (const std::string& n : a.names)
      if (n != "id") names.push_back(n);
    for (const std::string& n : b.names)
      if (n != "id" && std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);  // reported missing in A
  }
  if (a.particles != b.particles) {
    std::printf("particle counts differ: %zu and %zu\n", a.particles, b.particles);
    return 1;
  }
  std::printf("t = %.17g and %.17g, steps %lld and %lld, %zu particles\n", a.time, b.time, static_cast<long long>(a.step),
              static_cast<long long>(b.step), a.particles);
  const auto oa = by_id(a), ob = by_id(b);
  int c = 1;
  const auto *ida = field(a, "id", c), *idb = field(b, "id", c);
  for (std::size_t i = 0; i < a.particles; ++i)
    if ((*ida)[oa[i]] != (*idb)[ob[i]]) {
      std::printf("the particle ids differ\n");
      return 1;
    }
  // every id once (particles created and removed, e.g. at open boundaries, keep ids unique)
  for (std::size_t i = 1; i < a.particles; ++i)
    if ((*ida)[oa[i]] == (*ida)[oa[i - 1]]) {
      std::printf("id %.0f is carried by two particles\n", (*ida)[oa[i]]);
      return 1;
    }
  bool ok = true;
  for (const std::string& n : names) {
    int ca = 1, cb = 1;
    const auto *fa = field(a, n, ca), *fb = field(b, n, cb);
    if (!fa || !fb || ca != cb) {
      std::printf("%s: missing in one file\n", n.c_str());
      ok = false;
      continue;
    }
    double scale = 0, diff = 0;
    for (std::size_t i = 0; i < a.particles; ++i)
      for (int k = 0; k < ca; ++k) {
        const double va = (*fa)[oa[i] * ca + k], vb = (*fb)[ob[i] * ca + k];
        scale = std::max(scale, std::abs(va));
        diff = std::max(diff, std::abs(va - vb));
      }
    const double rel = scale > 0 ? diff / scale : diff;
    std::printf("%-10s max |a - b| / max |a| = %.3e%s\n", n.c_str(), rel, rel > tol ? "  ** above tolerance" : "");
    ok = ok && rel <= tol;
  }
  return ok ? 0 : 1;
}
