#pragma once
// A parsed, validated case file. Vectors are stored with 3 components; only the
// first `dimension` are meaningful. Units are SI throughout.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "kernels/InitialKinds.hpp"

namespace ondine {

using Vec3 = std::array<double, 3>;

enum class KernelType { WendlandC2, QuarticSpline, CubicSpline };
enum class EosLaw { Tait, Linear };
// The fluid flux: the centred scheme with delta-SPH (2.60) and artificial viscosity (2.58), or
// Riemann-SPH of Leduc et al. (2.90)-(2.101) with the acoustic solver (2.100)
enum class FluxScheme { DeltaSph, Riemann };
// Riemann-SPH's form: Leduc et al. (no mass flux, 2.90-2.101) or Vila's ALE form with mass
// fluxes (2.84-2.89)
enum class RiemannVariant { Leduc, Vila };
enum class ViscousTerm { None, Morris, MonaghanGingold };
enum class TimeIntegrator { RK4, PredictorCorrector };

// Eddy-viscosity turbulence models (Violeau & Issa, seed 000 §4.1.1): nu_T = L^2 sqrt(2 S:S)
// with the mixing length L_m or Smagorinsky's C_s dx, or nu_T = C_mu k^2 / epsilon with k and
// epsilon transported (k-epsilon, Launder & Spalding 1974); the log-law wall function on no-slip walls.
// The Generalised Langevin Model (V&I §4.1.2) moves the particles' velocities stochastically
// about their kernel-filtered mean, with epsilon from the mixing length.
enum class TurbulenceModel { None, MixingLength, Smagorinsky, KEpsilon, Langevin };
enum class WallLaw { None, Smooth, Rough };

struct Turbulence {
  TurbulenceModel model = TurbulenceModel::None;
  double kappa = 0.41;  // von Karman's constant
  // mixing length: a constant length (> 0), or the channel's kappa z sqrt(1 - z/H) with z the
  // height above the bed along `axis`
  double length = 0;
  int axis = -1;  // -1: no channel form
  double bed = 0, depth = 0;
  bool plane = false;  // a plane channel between walls at bed and bed + 2 depth (depth: the half-width)
  double smagorinsky_constant = 0.12;  // C_s, filter width dx
  WallLaw wall_function = WallLaw::None;
  double smooth_constant = 5.2;  // u/u* = ln(y u*/nu)/kappa + B on a smooth wall
  double roughness = 0;          // k_s (m): u/u* = ln(y/k_s)/kappa + B_r on a rough wall
  double rough_constant = 8.5;   // B_r (Nikuradse's fully rough constant)
  // k-epsilon: the standard constants and the initial state
  double c_mu = 0.09, c1 = 1.44, c2 = 1.92, sigma_k = 1.0, sigma_e = 1.3;
  double initial_k = 0, initial_epsilon = 0;  // m^2/s^2, m^2/s^3
  // Langevin: the drift's constants (LRR-IP), C0 (negative: Pope's relation), the stream's seed
  double langevin_c1 = 1.8, langevin_c2 = 0.6, langevin_c0 = -1;
  std::uint64_t seed = 0;
  bool langevin_averaged = false;  // turbulence.langevin.mean_gradient: averaged (kernels/turbulence/Langevin.hpp)
  bool langevin_drift_mean_removed = false;  // turbulence.langevin.drift_mean: removed (kernels/turbulence/Langevin.hpp)
  bool langevin_solenoidal = false;  // turbulence.langevin.noise: solenoidal (kernels/turbulence/Langevin.hpp)
  bool on() const { return model != TurbulenceModel::None; }
  // the model's nu_T enters the viscous terms (the Langevin model's stress is its particles' motion)
  bool eddy_viscous() const { return on() && model != TurbulenceModel::Langevin; }
};

struct Box {
  Vec3 min{0, 0, 0}, max{0, 0, 0};
};

struct FluidBlock {
  Box box;
  InitialVelocity velocity_kind = InitialVelocity::Uniform;
  Vec3 velocity{0, 0, 0};       // uniform velocity, m/s
  double tg_amplitude = 0.0;    // Taylor-Green U, m/s
  double tg_wavelength = 0.0;   // Taylor-Green L, m
  InitialPressure pressure_kind = InitialPressure::Zero;
  double wall_clearance = 0.5;  // in dx: lattice points closer than this to a wall are dropped
  // half-spaces that cut the block: lattice points with (x - point) . normal > 0 are dropped
  struct Cut {
    Vec3 point{0, 0, 0}, normal{0, 0, 0};  // normal: unit, out of the fluid
  };
  std::vector<Cut> cuts;
};

// A wall of the Normal Flux Method: a polyline (2D) of segments. The stored
// orientation is the fluid side; the normal out of the fluid (n_out, used by the
// operators) and into it (n_in, used by the Shepard formulas) derive from it.
enum class WallMotion { Fixed, Sliding, Translation, Oscillation, Rotation };
enum class WallCondition { NoSlip, Slip };

// A 3D wall: a triangle mesh in metres (after units, scaling, rotation and translation),
// each triangle ordered so that (v1 - v0) x (v2 - v0) points into the fluid (n_in).
struct WallMesh {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<int, 3>> triangles;
  std::string source;  // what it was built from, for messages: "box", "cylinder", "stl 'tank.stl'"...
};

struct Wall {
  std::string name;
  std::vector<std::array<double, 2>> points;  // 2D: vertices, in order
  WallMesh mesh;                              // 3D: the triangles
  bool closed = false;       // 2D: a closed polygon; 3D: a closed surface (a tank, a body)
  bool fluid_inside = true;  // closed: fluid inside; open 2D: fluid on the left of a->b (3D open: unused, the triangles' order tells)
  WallCondition condition = WallCondition::NoSlip;
  WallMotion motion = WallMotion::Fixed;
  Vec3 velocity{0, 0, 0};   // sliding: surface velocity; translation: body velocity (m/s)
  Vec3 amplitude{0, 0, 0};  // oscillation: x(t) = x0 + A sin(2 pi t / T) (m)
  double period = 0;        // oscillation period (s); rotation: the period of an oscillating angle
  // rotation about the axis through `centre` (2D: the z axis): angle(t) = omega t, or
  // angle_amplitude sin(2 pi t / period) with angle_amplitude > 0 (rad)
  Vec3 centre{0, 0, 0};
  Vec3 axis{0, 0, 1};       // unit
  double angular_velocity = 0, angle_amplitude = 0;
  Vec3 moment_centre{0, 0, 0};  // the point the moment of the fluid's force on the wall is taken about (m)
};

// The analytic or experimental reference a case is compared with (errors in summary.json).
enum class ReferenceKind { None, Poiseuille, Couette, Hydrostatic, MartinMoyce, GhiaRe100, GhiaRe1000, Duct, SphericTest2, Cylinder, OpenChannel, LogLaw, WedgeImpact };
struct Reference {
  ReferenceKind kind = ReferenceKind::None;
  double length = 0;  // poiseuille: channel height L; hydrostatic: water depth H; martin_moyce: column width a; ghia: cavity side; duct: side (m)
  Vec3 origin{0, 0, 0};  // poiseuille, couette: bottom wall point; hydrostatic: tank bottom; martin_moyce: back wall at the floor (m)
  double velocity = 0;   // couette: speed along x of the wall at y = origin + length, from t = 0 (m/s)
  // open_channel: length = H between the walls, origin = the bottom wall at the measured
  // section, velocity = the inlet's mean speed U (m/s)
  // log_law: length = the flow depth H, origin = a point of the bed; the friction velocity
  // u_* = sqrt(F H) of the momentum balance (F: body force and gravity along x), the law of turbulence:
  // (plane: a plane channel between walls at origin and origin + 2 length, length the half-width)
  std::string file;      // spheric_test2: the measured series; wedge_impact: the similarity profile (paths resolved against the case file's folder)
  // wedge_impact: length = s at the end of the comparison, velocity = U, origin = the contact
  // point on the wall, wall = the wall pushed, from = t0, the contact's time (s = U (t - t0))
  // cylinder: length = D, velocity = U of the stream, the wall whose force gives C_D, C_L and St,
  // counted from time `from` (s, after the start-up)
  std::string wall;
  double from = 0;
  bool plane = false;    // log_law: a plane channel
};

struct Probe {
  std::string name;
  Vec3 position{0, 0, 0};
};

// A pressure sensor on a wall (wall_sensors:): the NFM wall pressure P_p of (4.14) with the
// MUSCL state (4.30), Shepard-interpolated at points of the sensor's face (a square of side
// `size` centred at `position`, a segment in 2D, in the plane normal to `normal`) and
// averaged over it (solver/measures/WallLoads.hpp). `normal`: the wall's unit normal
// pointing out of the fluid (into the wall), as n_out of the wall points.
struct WallSensor {
  std::string name;
  Vec3 position{0, 0, 0};
  Vec3 normal{0, 0, 0};
  double size = 0;  // m; 0: a point sensor
};

// A wave gauge: a vertical line (along -gravity, the last axis) at `position`
// (its other coordinates), from `bottom` to `top` (m along that axis).
struct WaveGauge {
  std::string name;
  Vec3 position{0, 0, 0};
  double bottom = 0, top = 0;
};

// Adaptive particle refinement (thesis 5.4, docs/apr.md). A refinement zone is a
// box; a box nested in another refines one level further (level = depth). A box is
// static, translates with a prescribed velocity (with the boxes nested in it), or
// is re-centred every `every` steps on the maximum of the pressure or the speed
// inside its search region (with the boxes nested in it).
constexpr int kMaxRefinementLevel = 6;   // levels 0 (coarse) .. 6
constexpr int kMaxRefinementZones = 16;
enum class ZoneMotion { Static, Translation, Criterion };
enum class ZoneCriterion { Pressure, Speed };
struct RefinementZone {
  std::string name;
  Box box;
  int level = 1;    // depth: 1 for a top-level box
  int parent = -1;  // index of the enclosing box, -1 at the top level
  ZoneMotion motion = ZoneMotion::Static;
  Vec3 velocity{0, 0, 0};  // translation, m/s
  ZoneCriterion criterion = ZoneCriterion::Pressure;
  Box search;              // criterion: where the maximum is sought
  int every = 1;           // criterion: steps between re-centrings
};

// An open boundary (docs/case-file.md, "Open boundaries"): a plane normal to an axis with a
// buffer layer of `layers` dx on its outer side. Inlet: the buffer particles move with the
// imposed velocity and a particle that crosses the plane into the fluid is replaced by a new
// one `layers` dx upstream. Outlet: a fluid particle that crosses the plane joins the buffer,
// whose state is extrapolated from the fluid, and is removed at the buffer's outer face. The
// buffer state takes the incoming acoustic invariant from a reference state and the outgoing
// one from the fluid (non_reflecting), or imposes velocity (inlet) or pressure (outlet).
constexpr int kMaxOpenBoundaries = 8;
enum class OpenKind { Inlet, Outlet };
enum class InletProfile { Uniform, Parabolic };
struct OpenBoundary {
  std::string name;
  OpenKind kind = OpenKind::Inlet;
  int axis = 0;          // the plane is normal to this axis
  int sign = 1;          // +1: the fluid lies at larger coordinates (the normal into the fluid is +axis)
  double position = 0;   // the plane's coordinate along the axis (m)
  int layers = 0;        // buffer thickness in dx (at least R / dx)
  Vec3 velocity{0, 0, 0};  // inlet: the imposed velocity (the mean with a parabolic profile), m/s
  InletProfile profile = InletProfile::Uniform;
  int profile_axis = 1;  // parabolic: the axis across which u(s) = 6 U (s - lo)(hi - s) / (hi - lo)^2
  double span_lo = 0, span_hi = 0;
  double pressure = 0;   // outlet: the imposed mean pressure (Pa)
  bool non_reflecting = true;
  double relaxation_time = 0;  // s: the reference state's filter time (resolved: never 0 after parsing)
};

struct Scene {
  std::string name;         // case name (output folder name)
  std::string source_file;  // the YAML file it came from
  int dimension = 2;

  Box domain;
  std::array<bool, 3> periodic{false, false, false};

  // fluid
  double rho0 = 1000.0;         // kg/m^3
  double c0 = 0.0;              // m/s (resolved: never 'auto' after parsing)
  double mach = 0.1;            // used when sound_speed is auto
  double reference_velocity = 0.0;  // m/s, resolved
  double nu = 0.0;              // kinematic viscosity, m^2/s
  EosLaw eos = EosLaw::Tait;
  double tait_gamma = 7.0;
  double eos_background_pressure = 0.0;  // Pa, added to the law (flows without free surface)

  // discretisation
  KernelType kernel = KernelType::WendlandC2;
  double R_over_dx = 3.0;
  double dx = 0.0;  // m
  double R() const { return R_over_dx * dx; }

  std::vector<FluidBlock> blocks;
  std::vector<Wall> walls;
  double wall_quadrature_spacing = 0;  // m; 0: wall_quadrature_spacing_dx, or dx / 4 (2D), dx / 2 (3D)
  double wall_quadrature_spacing_dx = 0;  // in dx (of each refinement level in 3D); 0: unset

  Vec3 gravity{0, 0, 0};     // m/s^2
  Vec3 body_force{0, 0, 0};  // m/s^2 (force per unit mass)

  // scheme
  FluxScheme flux = FluxScheme::DeltaSph;
  bool riemann_muscl = true;  // Riemann-SPH: MUSCL reconstruction with minmod (2.78)-(2.83); false: first order
  bool riemann_low_dissipation = true;  // Riemann-SPH: the low-dissipation pressure of Zhang et al. (2017); false: (2.100) as printed
  RiemannVariant riemann_variant = RiemannVariant::Leduc;
  ViscousTerm viscous_term = ViscousTerm::None;
  Turbulence turbulence;              // turbulence: (Morris viscosity with nu + nu_T)
  double delta_sph = 0.0;             // 0 = no delta-SPH term (2.60)
  // scheme.delta_sph_form: hydrostatic: Psi_ij of (2.60) from the density less its hydrostatic part
  // (Fourtakas et al. 2019) instead of the renormalised gradients (kernels/terms/DeltaSphDiffusion.hpp)
  bool delta_sph_hydrostatic = false;
  double artificial_viscosity = 0.0;  // alpha of (2.58); 0 = off
  bool background_pressure = false;   // tensile correction (2.105)
  bool shifting = false;              // particle shifting (2.107)-(2.111) (scheme.transport: shifting)
  // c of the shift x += -c R^2 grad C (2.109): the thesis' 0.5, or (shifting_coefficient_stable)
  // the largest that damps the lattice's every mode monotonically (kernels/ShiftingStability.hpp)
  double shifting_coefficient = 0.5;
  bool shifting_coefficient_stable = false;
  bool ale = false;                   // the transport-velocity law of Oger et al. (2.112)-(2.115) (scheme.transport: ale)
  double ale_mach = 0.1;              // U_char = Ma c0 of (2.113)
  bool ale_tangential_cut = true;     // scheme.ale.cut_supports: tangential (kernels/OgerVelocityLaw.hpp); false: free
  bool consistent_laplacian = true;   // Morris scenes with no-slip walls: the consistent Laplacian (false: the thesis' operator)
  bool renormalised_continuity = false;  // drho/dt from the renormalised divergence (2.42-2.44, 4.86; kernels/RenormalisedContinuity.hpp)
  bool wall_contact = false;  // the wall's acoustic terms weighted by the fluid's contact (kernels/wall/WallContact.hpp)
  bool wall_velocity_reconstruction = false;  // MUSCL state of u at NFM wall points (4.30; kernels/WallVelocityState.hpp)
  TimeIntegrator integrator = TimeIntegrator::RK4;
  // the renormalised density gradient (2.42-2.44) read by delta-SPH and the MUSCL wall state:
  // false = computed at every stage of a step, true = at its first stage and held through the
  // others (one gradient pass per step instead of four with RK4)
  bool density_gradient_once_per_step = false;
  double cfl_acoustic = 0.375;  // (2.102)
  double cfl_viscous = 0.12;    // (2.103)
  double cfl_force = 0.25;      // [V&I 11]
  int reorder_interval = 50;    // steps between particle reorderings by cell
  double neighbour_skin = 0.3;  // Verlet skin, in dx (0: the list is rebuilt at every evaluation)
  // scheme.pair_list: half: the flux pass evaluates each pair once and updates both particles
  // (kernels/SymmetricFluxPass.hpp); the sums' order then depends on the thread count. After
  // parsing, true only where that pass is built (resolve_pair_list)
  bool half_pair_list = false;

  // time and output
  double duration = 0.0;         // s
  double output_interval = 0.0;  // s: the time series (probes, gauges, walls, diagnostics)
  int snapshot_every = 1;        // a snapshot at every n-th output instant (and the last)
  // time.output_at: next_step: an output at the end of the first step at or past each instant,
  // at that step's time, the step never shortened for it (but at the end); exact (false): the
  // step shortened to land on each instant
  bool output_at_next_step = false;
  std::int64_t max_steps = -1;   // -1: no limit
  double damping_time = 0;       // s: initial relaxation, u *= exp(-dt / (damping_time / 10)) while t < damping_time
  std::vector<Probe> probes;
  std::vector<WallSensor> wall_sensors;
  // adaptive particle refinement: empty = the uniform code path (no APR field, kernel or pass)
  std::vector<RefinementZone> refinement_zones;
  bool refinement_guard_shifting = false;  // shift the daughter guards towards a regular arrangement (kernels/apr/GuardSpacing.hpp)
  bool refinement_mother_shifting = false;  // shift the mother guards towards their daughters' volume (kernels/apr/GuardSpacing.hpp)
  double refinement_transition = 1.0;  // width of the daughter-guard layer, in R of the coarser level (thesis: R_m)
  // local time stepping by level: level l advances with step dt_0 / 2^l (Simulation<D>::step_local)
  bool refinement_local_time_stepping = false;
  // a dying mother's daughters inside their zone are adopted by the nearest mother guard (kernels/apr/Adoption.hpp)
  bool refinement_adoption = true;
  int max_refinement_level() const {
    int l = 0;
    for (const RefinementZone& z : refinement_zones) l = l > z.level ? l : z.level;
    return l;
  }
  std::vector<WaveGauge> wave_gauges;
  Reference reference;
  // inlets and outlets (empty: a closed or periodic domain, no open-boundary field or pass)
  std::vector<OpenBoundary> open_boundaries;

  // distributed runs: rebalance when tau = min work / max work (5.30) falls below this
  double rebalance_threshold = 0.9;
  bool balance_by_pairs = true;  // work of a cell: its pair interactions (5.5.2), or its particles
  // checkpoints (besides the one at a clean stop and at the end): 0 = never
  std::int64_t checkpoint_every_steps = 0;
  double checkpoint_every_wall_seconds = 0;
};

std::string to_string(KernelType);
std::string to_string(EosLaw);
std::string to_string(ViscousTerm);
std::string to_string(TimeIntegrator);
std::string to_string(FluxScheme);

// The scene has a no-slip wall (viscous wall-bounded flows get the consistent Laplacian,
// kernels/ConsistentLaplacian.hpp).
inline bool has_no_slip_wall(const Scene& s) {
  for (const Wall& w : s.walls)
    if (w.condition == WallCondition::NoSlip) return true;
  return false;
}

// Morris viscosity along no-slip walls takes the consistent Laplacian unless the case
// asks for the thesis' operator (scheme.consistent_laplacian: false) or a turbulence model
// (whose eddy viscosity varies from particle to particle: kernels/terms/EddyMorrisViscosity.hpp).
inline bool uses_consistent_laplacian(const Scene& s) {
  return s.viscous_term == ViscousTerm::Morris && s.consistent_laplacian && has_no_slip_wall(s) && !s.turbulence.on();
}

// The renormalised velocity gradient is gathered by the density-gradient pass (one neighbour loop
// for both): Riemann-SPH's MUSCL reconstruction (2.78) reads it, and so does the velocity's MUSCL
// state at NFM wall points (4.30, scheme.wall_velocity_reconstruction; kernels/WallVelocityState.hpp).
inline bool uses_velocity_gradient(const Scene& s) {
  return (s.flux == FluxScheme::Riemann && s.riemann_muscl) || (!s.walls.empty() && s.wall_velocity_reconstruction);
}

// The renormalised density gradient (2.42-2.44) is computed: delta-SPH (2.63), the MUSCL wall
// state (4.30), Riemann-SPH's MUSCL reconstruction (2.78).
inline bool uses_density_gradient(const Scene& s) { return s.delta_sph > 0 || !s.walls.empty() || uses_velocity_gradient(s); }

}  // namespace ondine
