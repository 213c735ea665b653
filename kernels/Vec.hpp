#pragma once
// Small fixed-size vector for device code (Eigen stays on the host, see docs/design.md).
#include <Kokkos_Core.hpp>

namespace ondine {

template <int D>
struct Vec {
  double c[D];

  KOKKOS_INLINE_FUNCTION double& operator[](int k) { return c[k]; }
  KOKKOS_INLINE_FUNCTION double operator[](int k) const { return c[k]; }

  KOKKOS_INLINE_FUNCTION static Vec zero() {
    Vec v;
    for (int k = 0; k < D; ++k) v.c[k] = 0.0;
    return v;
  }
  KOKKOS_INLINE_FUNCTION Vec& operator+=(const Vec& o) {
    for (int k = 0; k < D; ++k) c[k] += o.c[k];
    return *this;
  }
  KOKKOS_INLINE_FUNCTION Vec& operator-=(const Vec& o) {
    for (int k = 0; k < D; ++k) c[k] -= o.c[k];
    return *this;
  }
  KOKKOS_INLINE_FUNCTION Vec& operator*=(double s) {
    for (int k = 0; k < D; ++k) c[k] *= s;
    return *this;
  }
};

template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> operator+(Vec<D> a, const Vec<D>& b) { return a += b; }
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> operator-(Vec<D> a, const Vec<D>& b) { return a -= b; }
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> operator*(double s, Vec<D> a) { return a *= s; }
template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> operator*(Vec<D> a, double s) { return a *= s; }

template <int D>
KOKKOS_INLINE_FUNCTION double dot(const Vec<D>& a, const Vec<D>& b) {
  double s = 0.0;
  for (int k = 0; k < D; ++k) s += a.c[k] * b.c[k];
  return s;
}
template <int D>
KOKKOS_INLINE_FUNCTION double norm2(const Vec<D>& a) { return dot(a, a); }

// D x D matrix, row-major; used for the renormalisation matrix B_i (thesis 2.42-2.44).
template <int D>
struct Mat {
  double a[D][D];
  KOKKOS_INLINE_FUNCTION static Mat zero() {
    Mat m;
    for (int r = 0; r < D; ++r)
      for (int s = 0; s < D; ++s) m.a[r][s] = 0.0;
    return m;
  }
  KOKKOS_INLINE_FUNCTION static Mat identity() {
    Mat m = zero();
    for (int r = 0; r < D; ++r) m.a[r][r] = 1.0;
    return m;
  }
};

template <int D>
KOKKOS_INLINE_FUNCTION double determinant(const Mat<D>& m) {
  if constexpr (D == 2) {
    return m.a[0][0] * m.a[1][1] - m.a[0][1] * m.a[1][0];
  } else {
    return m.a[0][0] * (m.a[1][1] * m.a[2][2] - m.a[1][2] * m.a[2][1]) -
           m.a[0][1] * (m.a[1][0] * m.a[2][2] - m.a[1][2] * m.a[2][0]) +
           m.a[0][2] * (m.a[1][0] * m.a[2][1] - m.a[1][1] * m.a[2][0]);
  }
}

// Inverse by cofactors; returns false (and leaves `out` untouched) when |det| <= tiny.
template <int D>
KOKKOS_INLINE_FUNCTION bool invert(const Mat<D>& m, Mat<D>& out, double tiny) {
  const double det = determinant(m);
  if (!(det > tiny || det < -tiny)) return false;
  const double s = 1.0 / det;
  if constexpr (D == 2) {
    out.a[0][0] = m.a[1][1] * s;
    out.a[0][1] = -m.a[0][1] * s;
    out.a[1][0] = -m.a[1][0] * s;
    out.a[1][1] = m.a[0][0] * s;
  } else {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        const int r1 = (c + 1) % 3, r2 = (c + 2) % 3, c1 = (r + 1) % 3, c2 = (r + 2) % 3;
        out.a[r][c] = (m.a[r1][c1] * m.a[r2][c2] - m.a[r1][c2] * m.a[r2][c1]) * s;
      }
  }
  return true;
}

template <int D>
KOKKOS_INLINE_FUNCTION Vec<D> operator*(const Mat<D>& m, const Vec<D>& v) {
  Vec<D> r;
  for (int i = 0; i < D; ++i) {
    r.c[i] = 0.0;
    for (int k = 0; k < D; ++k) r.c[i] += m.a[i][k] * v.c[k];
  }
  return r;
}

}  // namespace ondine
