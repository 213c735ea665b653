#include "solver/WallModel.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/TriangleQuadrature.hpp"

namespace ondine {

namespace {

// Rigid displacement and velocity of a wall at time t.
void motion(const Wall& w, double t, double* disp, double* vel) {
  for (int k = 0; k < 3; ++k) disp[k] = vel[k] = 0;
  switch (w.motion) {
    case WallMotion::Fixed: break;
    case WallMotion::Sliding:  // geometry fixed, surface velocity (a lid)
      for (int k = 0; k < 3; ++k) vel[k] = w.velocity[k];
      break;
    case WallMotion::Translation:
      for (int k = 0; k < 3; ++k) {
        disp[k] = w.velocity[k] * t;
        vel[k] = w.velocity[k];
      }
      break;
    case WallMotion::Rotation: break;  // rotation(): about the wall's centre
    case WallMotion::Oscillation: {
      const double om = 2 * M_PI / w.period;
      for (int k = 0; k < 3; ++k) {
        disp[k] = w.amplitude[k] * std::sin(om * t);
        vel[k] = w.amplitude[k] * om * std::cos(om * t);
      }
      break;
    }
  }
}

// Rigid rotation of a wall at time t about its centre: the matrix Rm (row-major 3 x 3,
// Rodrigues' formula about the unit axis) and the angular velocity vector omega.
void rotation(const Wall& w, double t, double* Rm, double* omega) {
  double th = 0, rate = 0;
  if (w.motion == WallMotion::Rotation) {
    if (w.angle_amplitude > 0) {
      const double om = 2 * M_PI / w.period;
      th = w.angle_amplitude * std::sin(om * t);
      rate = w.angle_amplitude * om * std::cos(om * t);
    } else {
      th = w.angular_velocity * t;
      rate = w.angular_velocity;
    }
  }
  const double c = std::cos(th), s = std::sin(th), C = 1 - c;
  const double x = w.axis[0], y = w.axis[1], z = w.axis[2];
  const double R[9] = {c + x * x * C,     x * y * C - z * s, x * z * C + y * s,  //
                       y * x * C + z * s, c + y * y * C,     y * z * C - x * s,  //
                       z * x * C - y * s, z * y * C + x * s, c + z * z * C};
  for (int k = 0; k < 9; ++k) Rm[k] = R[k];
  for (int k = 0; k < 3; ++k) omega[k] = rate * w.axis[k];
}

// The facets and quadrature points of each wall, flattened (D coordinates per vertex or point).
struct HostWalls {
  std::vector<double> a, b, c, n_in;  // facets: vertices (c in 3D) and normal into the fluid
  std::vector<int> facet_wall;
  std::vector<double> qx, qn, qs;     // points: position, n_out, element length or area
  std::vector<int> qwall, qslip;
};

// 2D: each polyline's segments, each cut into elements no longer than hq with a midpoint point.
void add_polyline(const Wall& wall, int w, double hq, HostWalls& h) {
  const std::size_t np = wall.points.size();
  // orientation: a closed polygon's signed area tells on which side its inside lies
  double area2 = 0;
  for (std::size_t k = 0; k < np; ++k) {
    const auto& a = wall.points[k];
    const auto& b = wall.points[(k + 1) % np];
    area2 += a[0] * b[1] - b[0] * a[1];
  }
  // n_in = left normal of a->b for fluid on the left (open) or inside a counter-clockwise polygon
  bool left = wall.fluid_inside;
  if (wall.closed && area2 < 0) left = !left;
  const std::size_t nseg = wall.closed ? np : np - 1;
  for (std::size_t k = 0; k < nseg; ++k) {
    const auto& a = wall.points[k];
    const auto& b = wall.points[(k + 1) % np];
    const double tx = b[0] - a[0], ty = b[1] - a[1], len = std::hypot(tx, ty);
    const double nx = (left ? -ty : ty) / len, ny = (left ? tx : -tx) / len;  // n_in
    h.a.insert(h.a.end(), {a[0], a[1]});
    h.b.insert(h.b.end(), {b[0], b[1]});
    h.n_in.insert(h.n_in.end(), {nx, ny});
    h.facet_wall.push_back(w);
    const int m = std::max(1, static_cast<int>(std::ceil(len / hq)));
    for (int e = 0; e < m; ++e) {
      const double f = (e + 0.5) / m;
      h.qx.insert(h.qx.end(), {a[0] + f * tx, a[1] + f * ty});
      h.qn.insert(h.qn.end(), {-nx, -ny});  // n_out = -n_in
      h.qs.push_back(len / m);
      h.qwall.push_back(w);
      h.qslip.push_back(wall.condition == WallCondition::NoSlip ? 1 : 0);
    }
  }
}

// 3D: each triangle (ordered with (v1 - v0) x (v2 - v0) into the fluid by the parser), with
// the points of its clipped quadrature (§4.4, geometry/TriangleQuadrature.hpp) at spacing hq.
void add_mesh(const Wall& wall, int w, double hq, HostWalls& h) {
  const auto& V = wall.mesh.vertices;
  for (const auto& t : wall.mesh.triangles) {
    const Vec3 &p0 = V[t[0]], &p1 = V[t[1]], &p2 = V[t[2]];
    const Vec3 e1{p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]}, e2{p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    Vec3 n{e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (double& v : n) v /= len;
    h.a.insert(h.a.end(), p0.begin(), p0.end());
    h.b.insert(h.b.end(), p1.begin(), p1.end());
    h.c.insert(h.c.end(), p2.begin(), p2.end());
    h.n_in.insert(h.n_in.end(), n.begin(), n.end());
    h.facet_wall.push_back(w);
    for (const WallQuadraturePoint& q : clip_quadrature(p0, p1, p2, hq)) {
      h.qx.insert(h.qx.end(), q.x.begin(), q.x.end());
      h.qn.insert(h.qn.end(), {-n[0], -n[1], -n[2]});
      h.qs.push_back(q.area);
      h.qwall.push_back(w);
      h.qslip.push_back(wall.condition == WallCondition::NoSlip ? 1 : 0);
    }
  }
}

}  // namespace

template <int D>
WallModel<D>::WallModel(const Scene& scene, const PeriodicBox<D>& box, double cutoff, double spacing, bool facet_cells)
    : walls_(scene.walls), box_(box), cutoff_(cutoff), with_facet_cells_(facet_cells) {
  if (walls_.empty()) return;
  const double hq = spacing;
  HostWalls h;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const Wall& wall = walls_[w];
    names_.push_back(wall.name);
    moving_ = moving_ || wall.motion == WallMotion::Translation || wall.motion == WallMotion::Oscillation ||
              wall.motion == WallMotion::Sliding || wall.motion == WallMotion::Rotation;
    if constexpr (D == 2) add_polyline(wall, static_cast<int>(w), hq, h);
    else add_mesh(wall, static_cast<int>(w), hq, h);
  }
  auto to_device_vec = [](const std::vector<double>& v, const std::string& label) {
    const int n = static_cast<int>(v.size() / D);
    Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> d(label, n);
    auto hv = Kokkos::create_mirror_view(d);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < D; ++k) hv(i, k) = v[D * i + k];
    Kokkos::deep_copy(d, hv);
    return d;
  };
  auto to_device = [](const auto& v, const std::string& label) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    Kokkos::View<T*, MemSpace> d(label, v.size());
    Kokkos::deep_copy(d, Kokkos::View<const T*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(v.data(), v.size()));
    return d;
  };
  facets_.a = to_device_vec(h.a, "ondine::NFM::facet_a");
  facets_.b = to_device_vec(h.b, "ondine::NFM::facet_b");
  if (D == 3) facets_.c = to_device_vec(h.c, "ondine::NFM::facet_c");
  facets_.n_in = to_device_vec(h.n_in, "ondine::NFM::facet_n_in");
  facets_.wall = to_device(h.facet_wall, "ondine::NFM::facet_wall");
  facets_.count = static_cast<int>(h.facet_wall.size());
  host_a_ = h.a;
  host_b_ = h.b;
  host_c_ = h.c;
  host_facet_wall_ = h.facet_wall;
  points_.x = to_device_vec(h.qx, "ondine::NFM::point_x");
  points_.n_out = to_device_vec(h.qn, "ondine::NFM::point_n_out");
  points_.u = decltype(points_.u)("ondine::NFM::point_u", h.qs.size());
  points_.s = to_device(h.qs, "ondine::NFM::point_s");
  points_.wall = to_device(h.qwall, "ondine::NFM::point_wall");
  points_.no_slip = to_device(h.qslip, "ondine::NFM::point_no_slip");
  points_.count = static_cast<int>(h.qs.size());
  wall_velocity_ = decltype(wall_velocity_)("ondine::NFM::wall_velocity", walls_.size());
  if (moving_) {
    seg_a0_ = decltype(seg_a0_)("ondine::NFM::facet_a0", facets_.count);
    seg_b0_ = decltype(seg_b0_)("ondine::NFM::facet_b0", facets_.count);
    seg_c0_ = decltype(seg_c0_)("ondine::NFM::facet_c0", D == 3 ? facets_.count : 0);
    x0_ = decltype(x0_)("ondine::NFM::point_x0", points_.count);
    Kokkos::deep_copy(seg_a0_, facets_.a);
    Kokkos::deep_copy(seg_b0_, facets_.b);
    if (D == 3) Kokkos::deep_copy(seg_c0_, facets_.c);
    Kokkos::deep_copy(x0_, points_.x);
  }
  wall_spin_ = decltype(wall_spin_)("ondine::NFM::wall_spin", walls_.size());
  if (moving_) {  // the normals at rest, turned with rotating walls
    n_in0_ = decltype(n_in0_)("ondine::NFM::facet_n_in0", facets_.count);
    n_out0_ = decltype(n_out0_)("ondine::NFM::point_n_out0", points_.count);
    Kokkos::deep_copy(n_in0_, facets_.n_in);
    Kokkos::deep_copy(n_out0_, points_.n_out);
  }
  if (with_facet_cells_) facet_cells_ = make_facet_cells<D>(box_, cutoff_, host_a_, host_b_, host_c_, host_facet_wall_);
  move_to(0.0);
}

// The facet cells (kernels/WallSet.hpp) of facets (a, b, c: D coordinates per vertex, c empty
// in 2D; wall: the wall of each): a host loop over the facets and their periodic images, twice
// (count, then fill), so that each cell lists its entries by image, then facet.
template <int D>
FacetCells<D> make_facet_cells(const PeriodicBox<D>& box_, double cutoff_, const std::vector<double>& host_a_,
                               const std::vector<double>& host_b_, const std::vector<double>& host_c_,
                               const std::vector<int>& host_facet_wall_) {
  const CellGrid<D> g = make_cell_grid(box_, cutoff_);
  const int ncell = g.cells();
  const double reach = cutoff_ * (1.0 + 1e-9);
  std::vector<int> start(static_cast<std::size_t>(ncell) + 1, 0), facet, image;
  std::vector<int> cursor;
  int images = 1;
  for (int k = 0; k < D; ++k) images *= 3;
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      for (int c = 0; c < ncell; ++c) start[c + 1] += start[c];
      facet.resize(start[ncell]);
      image.resize(start[ncell]);
      cursor.assign(start.begin(), start.end() - 1);
    }
    // images in the order of nested loops over axes, the first axis outermost
    for (int m = 0; m < images; ++m) {
      int o[D], code = 0, rest = m, weight = 1;
      bool used = true;
      for (int k = D - 1; k >= 0; --k) {
        o[k] = rest % 3 - 1;
        rest /= 3;
        if (o[k] != 0 && !box_.periodic[k]) used = false;
      }
      if (!used) continue;
      for (int k = 0; k < D; ++k, weight *= 3) code += (o[k] + 1) * weight;
      for (int s = 0; s < static_cast<int>(host_facet_wall_.size()); ++s) {
        int lo[D], hi[D];
        bool empty = false;
        for (int k = 0; k < D; ++k) {
          const double d = -o[k] * box_.len[k];
          double vmin = host_a_[D * s + k], vmax = vmin;
          for (const std::vector<double>* v : {&host_b_, &host_c_})
            if (!v->empty()) {
              vmin = std::min(vmin, (*v)[D * s + k]);
              vmax = std::max(vmax, (*v)[D * s + k]);
            }
          const double fl = std::floor((vmin + d - reach - g.lo[k]) * g.inv_size[k]);
          const double fh = std::floor((vmax + d + reach - g.lo[k]) * g.inv_size[k]);
          if (g.periodic[k]) {  // cells beyond the box belong to another image
            lo[k] = static_cast<int>(std::max(fl, 0.0));
            hi[k] = static_cast<int>(std::min(fh, g.n[k] - 1.0));
            if (lo[k] > hi[k]) empty = true;
          } else {  // an edge cell also holds the particles beyond the box
            lo[k] = static_cast<int>(std::min(std::max(fl, 0.0), g.n[k] - 1.0));
            hi[k] = static_cast<int>(std::min(std::max(fh, 0.0), g.n[k] - 1.0));
          }
        }
        if (empty) continue;
        int c[D];
        for (int k = 0; k < D; ++k) c[k] = lo[k];
        while (true) {
          const int idx = g.linear(c);
          if (pass == 0) {
            ++start[idx + 1];
          } else {
            facet[cursor[idx]] = s;
            image[cursor[idx]++] = code;
          }
          int k = 0;
          while (k < D && ++c[k] > hi[k]) {
            c[k] = lo[k];
            ++k;
          }
          if (k == D) break;
        }
      }
    }
  }
  auto to_device = [](const std::vector<int>& v, const std::string& label) {
    Kokkos::View<int*, MemSpace> d(label, v.size());
    Kokkos::deep_copy(d, Kokkos::View<const int*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(v.data(), v.size()));
    return d;
  };
  FacetCells<D> cells;
  cells.grid = g;
  cells.start = to_device(start, "ondine::NFM::facet_cell_start");
  cells.facet = to_device(facet, "ondine::NFM::facet_cell_facet");
  cells.image = to_device(image, "ondine::NFM::facet_cell_image");
  return cells;
}

template <int D>
FacetCells<D> make_facet_cells(const PeriodicBox<D>& box, double cutoff, const WallFacets<D>& f) {
  auto host = [&](const Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace>& v) {
    std::vector<double> out;
    if (v.extent(0) == 0) return out;
    auto h = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), v);
    for (int s = 0; s < f.count; ++s)
      for (int k = 0; k < D; ++k) out.push_back(h(s, k));
    return out;
  };
  auto hw = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), f.wall);
  std::vector<int> wall(hw.data(), hw.data() + f.count);
  return make_facet_cells<D>(box, cutoff, host(f.a), host(f.b), D == 3 ? host(f.c) : std::vector<double>(), wall);
}

// Wall positions and velocities at time t. Each wall moves rigidly: x = c + Rm (x0 - c) + d,
// normals Rm n0, velocity v + omega x (x - c), with d, v of its translation or oscillation and
// Rm, omega of its rotation about c (the identity and zero for a wall that does not rotate, which
// leaves x0 + d and v bit for bit). The facet cells are rebuilt from the moved vertices (host
// loops over walls and facets, not particles) whenever a wall is away from its rest position.
template <int D>
void WallModel<D>::move_to(double t) {
  if (walls_.empty()) return;
  if (moving_) {
    const int nw = static_cast<int>(walls_.size());
    Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> disp("ondine::NFM::wall_disp", nw), vel("ondine::NFM::wall_vel", nw);
    Kokkos::View<double* [9], Kokkos::LayoutRight, MemSpace> rot("ondine::NFM::wall_rotation", nw);
    auto hd = Kokkos::create_mirror_view(disp);
    auto hv = Kokkos::create_mirror_view(vel);
    auto hr = Kokkos::create_mirror_view(rot);
    auto hs = Kokkos::create_mirror_view(wall_spin_);
    bool away = false;  // some wall is displaced or turned
    for (int w = 0; w < nw; ++w) {
      double d3[3], v3[3], R[9], om[3];
      motion(walls_[w], t, d3, v3);
      rotation(walls_[w], t, R, om);
      for (int k = 0; k < D; ++k) {
        hd(w, k) = d3[k];
        hv(w, k) = v3[k];
        away = away || d3[k] != 0.0;
      }
      for (int k = 0; k < 9; ++k) {
        hr(w, k) = R[k];
        away = away || R[k] != (k % 4 == 0 ? 1.0 : 0.0);
      }
      for (int k = 0; k < 3; ++k) {
        hs(w, k) = om[k];
        hs(w, 3 + k) = walls_[w].centre[k];
      }
    }
    Kokkos::deep_copy(disp, hd);
    Kokkos::deep_copy(vel, hv);
    Kokkos::deep_copy(rot, hr);
    Kokkos::deep_copy(wall_spin_, hs);
    Kokkos::deep_copy(wall_velocity_, vel);
    place_points_and_facets(disp, vel, rot);
    if (with_facet_cells_ && (away || facets_moved_)) {
      // the facet cells of the moved facets, from host copies of the vertices
      std::vector<double> ta(host_a_.size()), tb(host_b_.size()), tc(host_c_.size());
      auto place = [&](const std::vector<double>& from, std::vector<double>& to) {
        for (std::size_t s = 0; s < host_facet_wall_.size() && !from.empty(); ++s) {
          const int w = host_facet_wall_[s];
          for (int k = 0; k < D; ++k) {
            double v = hs(w, 3 + k) + hd(w, k);
            for (int l = 0; l < D; ++l) v += hr(w, 3 * k + l) * (from[D * s + l] - hs(w, 3 + l));
            to[D * s + k] = v;
          }
        }
      };
      place(host_a_, ta);
      place(host_b_, tb);
      place(host_c_, tc);
      facet_cells_ = make_facet_cells<D>(box_, cutoff_, ta, tb, tc, host_facet_wall_);
    }
    facets_moved_ = away;
  }
  cells_.build(make_cell_grid(box_, cutoff_), points_.x, points_.count);
}

// The points and facets of the walls placed by their rigid motions (see move_to).
template <int D>
void WallModel<D>::place_points_and_facets(const Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace>& disp,
                                           const Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace>& vel,
                                           const Kokkos::View<double* [9], Kokkos::LayoutRight, MemSpace>& rot) {
  const auto spin = wall_spin_;
  // v <- c + d + Rm (v0 - c), in the first D coordinates (2D: about z)
  const auto place = KOKKOS_LAMBDA(const int w, const double* v0, double* v) {
    double r[3] = {0, 0, 0};
    for (int k = 0; k < D; ++k) r[k] = v0[k] - spin(w, 3 + k);
    for (int k = 0; k < D; ++k) {
      double s = spin(w, 3 + k) + disp(w, k);
      for (int l = 0; l < D; ++l) s += rot(w, 3 * k + l) * r[l];
      v[k] = s;
    }
  };
  // n <- Rm n0 (a normal)
  const auto turn_normal = KOKKOS_LAMBDA(const int w, const double* n0, double* n) {
    for (int k = 0; k < D; ++k) {
      n[k] = 0;
      for (int l = 0; l < D; ++l) n[k] += rot(w, 3 * k + l) * n0[l];
    }
  };
  const auto px = points_.x, pu = points_.u, pn = points_.n_out, x0 = x0_, n0 = n_out0_;
  const auto pw = points_.wall;
  Kokkos::parallel_for("ondine::NFM::move_points", Kokkos::RangePolicy<ExecSpace>(0, points_.count), KOKKOS_LAMBDA(const int q) {
    const int w = pw(q);
    double v0[3] = {0, 0, 0}, v[3] = {0, 0, 0}, n[3] = {0, 0, 0};
    for (int k = 0; k < D; ++k) v0[k] = x0(q, k);
    place(w, v0, v);
    for (int k = 0; k < D; ++k) v0[k] = n0(q, k);
    turn_normal(w, v0, n);
    double r[3] = {0, 0, 0};  // x - c
    for (int k = 0; k < D; ++k) r[k] = v[k] - spin(w, 3 + k);
    const double cr[3] = {spin(w, 1) * r[2] - spin(w, 2) * r[1], spin(w, 2) * r[0] - spin(w, 0) * r[2],
                          spin(w, 0) * r[1] - spin(w, 1) * r[0]};
    for (int k = 0; k < D; ++k) {
      px(q, k) = v[k];
      pn(q, k) = n[k];
      pu(q, k) = vel(w, k) + cr[k];
    }
  });
  const auto a = facets_.a, b = facets_.b, c = facets_.c, a0 = seg_a0_, b0 = seg_b0_, c0 = seg_c0_;
  const auto fn = facets_.n_in, fn0 = n_in0_;
  const auto sw = facets_.wall;
  using Rows = Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace>;
  Kokkos::parallel_for("ondine::NFM::move_facets", Kokkos::RangePolicy<ExecSpace>(0, facets_.count), KOKKOS_LAMBDA(const int s) {
    const int w = sw(s);
    // row s of `to` from row s of `from`: a vertex placed, or the normal turned
    const auto move = [&](const Rows& from, const Rows& to, const bool normal) {
      double v0[3] = {0, 0, 0}, v[3] = {0, 0, 0};
      for (int k = 0; k < D; ++k) v0[k] = from(s, k);
      if (normal) turn_normal(w, v0, v);
      else place(w, v0, v);
      for (int k = 0; k < D; ++k) to(s, k) = v[k];
    };
    move(a0, a, false);
    move(b0, b, false);
    if (D == 3) move(c0, c, false);
    move(fn0, fn, true);
  });
}

template class WallModel<2>;
template class WallModel<3>;
template FacetCells<2> make_facet_cells<2>(const PeriodicBox<2>&, double, const WallFacets<2>&);
template FacetCells<3> make_facet_cells<3>(const PeriodicBox<3>&, double, const WallFacets<3>&);

}  // namespace ondine
