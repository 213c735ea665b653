#pragma once
// Reference solutions computed in code, and published data typed in with their source. They
// take parameters, not scenes (observers/ reads a scene's reference and calls them).
#include <array>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace ondine::reference {

// Start-up plane Poiseuille flow between walls y = 0 and y = L driven by a body
// force F (Morris et al. 1997, eq. 21): u(y, t) = F/(2 nu) y (L - y)
//   - sum_n 4 F L^2 / (nu pi^3 (2n+1)^3) sin(pi y (2n+1) / L) exp(-(2n+1)^2 pi^2 nu t / L^2).
double poiseuille_startup(double y, double t, double L, double F, double nu);

// Start-up plane Couette flow between walls y = 0 (at rest) and y = L (moving at V0 along x
// from t = 0; Morris et al. 1997): u(y, t) = V0 y / L
//   + sum_{n>=1} 2 V0 (-1)^n / (n pi) sin(n pi y / L) exp(-n^2 pi^2 nu t / L^2).
double couette_startup(double y, double t, double L, double V0, double nu);

// Start-up laminar flow along x in a square duct 0 < y, z < L driven by a body force F
// (the double sine series of nu lap u = -F with u = 0 on the walls):
//   u(y, z, t) = F/(2 nu) y (L - y) - sum_{n odd} 4 F L^2 / (nu pi^3 n^3) sin(n pi y / L)
//                  cosh(n pi (z - L/2) / L) / cosh(n pi / 2)                                  (steady)
//              - sum_{m, n odd} 16 F L^2 / (nu pi^4 m n (m^2 + n^2)) sin(m pi y / L) sin(n pi z / L)
//                  exp(-(m^2 + n^2) pi^2 nu t / L^2)                                          (transient)
double duct_startup(double y, double z, double t, double L, double F, double nu);

// Martin & Moyce (1952), n^2 = 2, Table 2: surge front Z = x/a against T = t sqrt(2 g / a)
// (cases/reference/martin_moyce1952_front_n2_2.csv gives the source chain of these digits).
const std::vector<std::pair<double, double>>& martin_moyce_front();

// Errors of a simulated surge front (T, Z) against Martin & Moyce for 0.3 <= T <= 3:
// front_max_relative_error (max |Z - Z_exp| / Z_exp), front_speed (least-squares dZ/dT over
// 1.5 <= T <= 3) and front_speed_relative_error against the experiment's slope there.
std::map<std::string, double> martin_moyce_errors(const std::vector<std::pair<double, double>>& front);

// Largest relative difference of a surge front (T, Z) from a contrast front over 0.3 <= T <= 3:
// max |Z - Z_c(T)| / Z_c(T), Z_c interpolated linearly (front_contrast_difference). NaN when the
// contrast front is empty.
double front_relative_difference(const std::vector<std::pair<double, double>>& front,
                                 const std::vector<std::pair<double, double>>& contrast);

// Area of a simple polygon (shoelace formula; either orientation), m^2.
double polygon_area(const std::vector<std::array<double, 2>>& points);

// Numeric rows of a CSV file ('#' comments and the header line skipped).
std::vector<std::vector<double>> read_table(const std::string& path);

// Linear interpolation of a sampled series (x sorted); clamps outside the range.
double interpolate(const std::vector<std::pair<double, double>>& series, double x);

}  // namespace ondine::reference
