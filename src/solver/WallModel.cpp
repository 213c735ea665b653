#include "solver/WallModel.hpp"

#include <cmath>
#include <stdexcept>

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

}  // namespace

template <int D>
WallModel<D>::WallModel(const Scene& scene, const PeriodicBox<D>& box, double cutoff)
    : walls_(scene.walls), box_(box), cutoff_(cutoff) {
  if (walls_.empty()) return;
  if (D != 2) throw std::invalid_argument("NFM walls are implemented in 2D only");
  const double hq = scene.wall_quadrature_spacing > 0 ? scene.wall_quadrature_spacing : scene.dx / 4;
  std::vector<double> sa, sb, sn;  // segments, flattened (x, y)
  std::vector<int> swall;
  std::vector<double> qx, qn, qs;
  std::vector<int> qwall, qslip;
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    const Wall& wall = walls_[w];
    names_.push_back(wall.name);
    moving_ = moving_ || wall.motion == WallMotion::Translation || wall.motion == WallMotion::Oscillation ||
              wall.motion == WallMotion::Sliding;
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
      sa.insert(sa.end(), {a[0], a[1]});
      sb.insert(sb.end(), {b[0], b[1]});
      sn.insert(sn.end(), {nx, ny});
      swall.push_back(static_cast<int>(w));
      const int m = std::max(1, static_cast<int>(std::ceil(len / hq)));
      for (int e = 0; e < m; ++e) {
        const double f = (e + 0.5) / m;
        qx.insert(qx.end(), {a[0] + f * tx, a[1] + f * ty});
        qn.insert(qn.end(), {-nx, -ny});  // n_out = -n_in
        qs.push_back(len / m);
        qwall.push_back(static_cast<int>(w));
        qslip.push_back(wall.condition == WallCondition::NoSlip ? 1 : 0);
      }
    }
  }
  auto to_device_vec = [](const std::vector<double>& v, const std::string& label) {
    const int n = static_cast<int>(v.size() / D);
    Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> d(label, n);
    auto h = Kokkos::create_mirror_view(d);
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < D; ++k) h(i, k) = v[D * i + k];
    Kokkos::deep_copy(d, h);
    return d;
  };
  auto to_device = [](const auto& v, const std::string& label) {
    using T = typename std::decay_t<decltype(v)>::value_type;
    Kokkos::View<T*, MemSpace> d(label, v.size());
    Kokkos::deep_copy(d, Kokkos::View<const T*, Kokkos::HostSpace, Kokkos::MemoryUnmanaged>(v.data(), v.size()));
    return d;
  };
  segments_.a = to_device_vec(sa, "ondine::NFM::segment_a");
  segments_.b = to_device_vec(sb, "ondine::NFM::segment_b");
  segments_.n_in = to_device_vec(sn, "ondine::NFM::segment_n_in");
  segments_.wall = to_device(swall, "ondine::NFM::segment_wall");
  segments_.count = static_cast<int>(swall.size());
  points_.x = to_device_vec(qx, "ondine::NFM::point_x");
  points_.n_out = to_device_vec(qn, "ondine::NFM::point_n_out");
  points_.u = decltype(points_.u)("ondine::NFM::point_u", qs.size());
  points_.s = to_device(qs, "ondine::NFM::point_s");
  points_.wall = to_device(qwall, "ondine::NFM::point_wall");
  points_.no_slip = to_device(qslip, "ondine::NFM::point_no_slip");
  points_.count = static_cast<int>(qs.size());
  wall_velocity_ = decltype(wall_velocity_)("ondine::NFM::wall_velocity", walls_.size());
  if (moving_) {
    seg_a0_ = decltype(seg_a0_)("ondine::NFM::segment_a0", segments_.count);
    seg_b0_ = decltype(seg_b0_)("ondine::NFM::segment_b0", segments_.count);
    x0_ = decltype(x0_)("ondine::NFM::point_x0", points_.count);
    Kokkos::deep_copy(seg_a0_, segments_.a);
    Kokkos::deep_copy(seg_b0_, segments_.b);
    Kokkos::deep_copy(x0_, points_.x);
  }
  move_to(0.0);
}

template <int D>
void WallModel<D>::move_to(double t) {
  if (walls_.empty()) return;
  if (moving_) {
    // per-wall rigid displacement and velocity (a loop over walls, not particles)
    const int nw = static_cast<int>(walls_.size());
    Kokkos::View<double* [D], Kokkos::LayoutLeft, MemSpace> disp("ondine::NFM::wall_disp", nw), vel("ondine::NFM::wall_vel", nw);
    auto hd = Kokkos::create_mirror_view(disp);
    auto hv = Kokkos::create_mirror_view(vel);
    for (int w = 0; w < nw; ++w) {
      double d3[3], v3[3];
      motion(walls_[w], t, d3, v3);
      for (int k = 0; k < D; ++k) {
        hd(w, k) = d3[k];
        hv(w, k) = v3[k];
      }
    }
    Kokkos::deep_copy(disp, hd);
    Kokkos::deep_copy(vel, hv);
    Kokkos::deep_copy(wall_velocity_, vel);
    const auto px = points_.x, pu = points_.u, x0 = x0_;
    const auto pw = points_.wall;
    Kokkos::parallel_for("ondine::NFM::move_points", Kokkos::RangePolicy<ExecSpace>(0, points_.count), KOKKOS_LAMBDA(const int q) {
      for (int k = 0; k < D; ++k) {
        px(q, k) = x0(q, k) + disp(pw(q), k);
        pu(q, k) = vel(pw(q), k);
      }
    });
    const auto a = segments_.a, b = segments_.b, a0 = seg_a0_, b0 = seg_b0_;
    const auto sw = segments_.wall;
    Kokkos::parallel_for("ondine::NFM::move_segments", Kokkos::RangePolicy<ExecSpace>(0, segments_.count), KOKKOS_LAMBDA(const int s) {
      for (int k = 0; k < D; ++k) {
        a(s, k) = a0(s, k) + disp(sw(s), k);
        b(s, k) = b0(s, k) + disp(sw(s), k);
      }
    });
  }
  cells_.build(make_cell_grid(box_, cutoff_), points_.x, points_.count);
}

template class WallModel<2>;
template class WallModel<3>;

}  // namespace ondine
