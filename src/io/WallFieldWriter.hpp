#pragma once
// The load on the walls point by point, beside each snapshot: <dir>/walls/<case>_<NNNNNN>.h5
// holds every wall quadrature point's position, outward normal, wall pressure and traction,
// and <dir>/<case>_walls.xmf indexes them as a time series ParaView opens next to the
// particles' (the same instants). Written by rank 0 through a temporary name and a rename.
#include <cstdint>
#include <string>
#include <vector>

#include "parallel/Communicator.hpp"

namespace ondine {

// Each wall quadrature point's position and outward normal (N x 3, z = 0 in 2D), the wall
// pressure P_p of the normal flux (4.14) Shepard-interpolated there (Pa), the traction, the
// pressure and viscous force per unit of wall area (N x 3, Pa), its quadrature weight s (m in
// 2D, m^2 in 3D) and its wall's index in the case file (solver/Measures.hpp: wall_load_field).
struct WallLoadField {
  std::vector<double> position, normal, pressure, traction, area, wall;
  std::size_t points() const { return pressure.size(); }
};

class WallFieldWriter {
 public:
  WallFieldWriter(std::string dir, std::string case_name, Communicator comm = Communicator());

  void write(const WallLoadField& f, double time, std::int64_t step);
  // a restarted run: keeps the first `count` files in the folder as its own, removes the later ones
  void resume(std::size_t count);
  // removes this case's wall files numbered `first` or more (a new run calls it with 0)
  void remove_from(std::size_t first) const;
  std::string index_path() const;
  std::size_t count() const { return entries_.size(); }

 private:
  struct Entry {
    std::string file;
    double time;
    std::size_t points;
  };
  void write_index() const;
  std::string file_name(std::size_t index) const;
  std::string dir_, name_;
  Communicator comm_;
  std::vector<Entry> entries_;
};

}  // namespace ondine
