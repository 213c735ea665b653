// ondine: command-line entry point.
#include <CLI/CLI.hpp>
#include <Kokkos_Core.hpp>
#include <mpi.h>
#ifdef KOKKOS_ENABLE_CUDA
#include <cuda_runtime.h>
#endif

#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <system_error>

#include "run/BuildInfo.hpp"
#include "app/KernelProfile.hpp"
#include "app/Validate.hpp"
#include "io/AtomicFile.hpp"
#include "io/Checkpoint.hpp"
#include "scene/CaseFile.hpp"
#include "scene/MemoryEstimate.hpp"
#include "run/Runner.hpp"

namespace {

void on_signal(int sig) { ondine::request_stop(sig); }

std::string version_text() {
  std::string b;
  for (const auto& s : ondine::kokkos_backends()) b += (b.empty() ? "" : ", ") + s;
  return "ondine " + ondine::ondine_version() + "\nKokkos " + ondine::kokkos_version() + " (backends: " + b +
         "; default execution space: " + ondine::default_backend() + ")\n";
}

// Why the CUDA build cannot run here (no device, or a driver older than the runtime), or ""
// where it can, or in a CPU build. Asked before Kokkos' initialisation, which would throw
// from inside its CUDA set-up and leave a stack trace.
std::string cuda_device_problem() {
#ifdef KOKKOS_ENABLE_CUDA
  int n = 0;
  const cudaError_t e = cudaGetDeviceCount(&n);
  if (e != cudaSuccess) return cudaGetErrorString(e);
  if (n == 0) return "no CUDA device found";
#endif
  return "";
}

// `no_device`: the CUDA build without a usable device (cuda_device_problem): --help and
// --version answer, a run or a validation stops before it reads or writes anything.
int run_app(int argc, char** argv, int ranks, int rank, const std::string& no_device) {
  CLI::App app{"Ondine: data-parallel SPH for free-surface hydrodynamics (Kokkos)", "ondine"};
  const std::string threads_note =
      "Threads: OMP_NUM_THREADS sets their number. Unless OMP_PROC_BIND or OMP_PLACES is set, ondine binds them with "
      "OMP_PROC_BIND=spread OMP_PLACES=threads (one process) or leaves them unbound under mpirun with several ranks "
      "(Open MPI binds the ranks); an explicit setting always wins.";
  app.footer(threads_note);
  app.set_version_flag("--version", version_text());
  app.require_subcommand(1);
  auto* run = app.add_subcommand("run", "run a case file to completion");
  std::string case_file, out_dir, restart;
  std::vector<std::string> sets;
  bool quiet = false, profile = false;
  run->add_option("CASE", case_file, "YAML case file (see docs/case-file.md)")->required();
  run->add_option("--out", out_dir, "output folder (default: out/<case name>)");
  run->add_option("--set", sets, "override a case key, e.g. --set discretisation.dx=0.01 (repeatable)");
  run->add_flag("--quiet", quiet, "no progress line");
  run->add_flag("--profile", profile, "wall time of every Kokkos kernel (rank 0's) -> OUT/profile_kernels.json");
  run->add_option("--restart", restart, "continue from a checkpoint (OUT/checkpoint.h5), on any number of ranks");
  run->footer(threads_note);
  auto* validate = app.add_subcommand("validate", "run the validation cases over a resolution ladder (docs/validation.md)");
  ondine::ValidateOptions vopt;
  validate->add_option("--case", vopt.cases, "case name (repeatable; default: all)");
  validate->add_option("--level", vopt.level, "quick (the CI subset) or full (the whole ladder)");
  validate->add_option("--out", vopt.out_dir, "output folder (default: out/validation)");
  validate->add_flag("--list", vopt.list, "print the validation cases (name, group, case file) and run nothing");
  validate->add_flag("--dry-run", vopt.dry_run,
                     "resolve every chosen run (case file, overrides, named flux scheme) and run nothing; exit 1 when one is refused");
  validate->add_option("--flux", vopt.flux,
                       "case (each case file's), delta_sph (the thesis' delta-SPH, 2.60), delta_sph_hydrostatic (the same with scheme.delta_sph_form: hydrostatic), riemann (Riemann-SPH with MUSCL, Leduc's form) or riemann_vila (Vila's form with mass fluxes): the fluid flux of every run (docs/case-file.md scheme.flux)");
  validate->add_option("--transport", vopt.transport,
                       "case (each case file's), lagrangian, shifting, ale (Oger's transport velocity; with --flux riemann or riemann_vila) or ale_free (the same with scheme.ale.cut_supports: free): the particle transport of every run (docs/case-file.md scheme.transport)");
  validate->add_flag("--resume", vopt.resume,
                     "take the rungs completed in OUT as they are and continue those stopped (a signal, the end of a session) from "
                     "their checkpoints; every rung writes a checkpoint every 10 wall minutes. A folder holding a run of other "
                     "settings is refused");
  validate->add_option("--variant", vopt.variants,
                       "run only this rung of a ladder (its folder's name: coarse, apr, apr_lts, fine, apr_s40, ...; repeatable); the "
                       "others are left out of the report");
  // a first word that is no command: CLI11 says only that a subcommand is required
  if (argc > 1 && argv[1][0] != '-' && std::string(argv[1]) != "run" && std::string(argv[1]) != "validate") {
    if (rank == 0)
      std::fprintf(stderr, "ondine: error: unknown command '%s': expected run or validate (ondine --help)\n", argv[1]);
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  if (!no_device.empty()) {
    if (rank == 0)
      std::fprintf(stderr, "ondine: error: this is the CUDA build of ondine, and it needs a CUDA device: %s; build/ondine is the CPU build\n",
                   no_device.c_str());
    return 2;
  }
  if (validate->parsed()) {
    if (ranks > 1) {
      if (rank == 0) std::fprintf(stderr, "ondine: error: validate runs on one rank (its cases write to one folder); run it without mpirun\n");
      return 2;
    }
    vopt.source_dir = ONDINE_SOURCE_DIR;
    std::signal(SIGINT, on_signal);  // the running rung writes its checkpoint and the validation stops
    std::signal(SIGTERM, on_signal);
    try {
      return ondine::run_validation(vopt);
    } catch (const ondine::CaseError& e) {
      std::fprintf(stderr, "ondine: error: %s\n", e.what());
      return 2;
    }
  }

  ondine::Scene scene;
  try {
    scene = ondine::load_case(case_file, sets);
  } catch (const ondine::CaseError& e) {
    std::fprintf(stderr, "ondine: error: %s\n", e.what());
    return 2;
  }
  ondine::RunOptions opt;
  if (run->get_option("--out")->count() > 0 && out_dir.empty()) {
    if (rank == 0) std::fprintf(stderr, "ondine: error: --out: expected a folder, got an empty name\n");
    return 2;
  }
  opt.out_dir = out_dir.empty() ? "out/" + scene.name : out_dir;
  {
    std::error_code ec;  // a file in the output folder's place, before anything is said (the runner creates the folder)
    if (std::filesystem::exists(opt.out_dir, ec) && !std::filesystem::is_directory(opt.out_dir, ec)) {
      if (rank == 0) std::fprintf(stderr, "ondine: error: --out %s: a file of that name exists; expected a folder\n", opt.out_dir.c_str());
      return 2;
    }
  }
  opt.progress = !quiet && rank == 0;
  opt.restart = restart;
  if (rank == 0)
    std::fprintf(stderr, "ondine: case %s (%dD), dx = %g m, c0 = %g m/s, %d rank%s x backend %s x %d -> %s%s%s\n",
                 scene.name.c_str(), scene.dimension, scene.dx, scene.c0, ranks, ranks > 1 ? "s" : "",
                 ondine::default_backend().c_str(), ondine::backend_threads(), opt.out_dir.c_str(),
                 restart.empty() ? "" : ", restart from ", restart.c_str());
  if (rank == 0) std::fprintf(stderr, "ondine: %s\n", ondine::estimate_memory(scene).summary().c_str());
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  ondine::RunReport r;
  if (profile) ondine::install_kernel_profile();
  try {
    r = ondine::run_scene(scene, opt);
  } catch (const ondine::CheckpointError& e) {
    if (rank == 0) std::fprintf(stderr, "ondine: error: cannot restart: %s\n", e.what());
    return 2;
  }
  if (rank == 0) {
    std::fprintf(stderr, "ondine: %s: %zu particles, %lld steps, t = %g s, %.2f s wall, %.3g particle-steps/s\n", r.status.c_str(),
                 r.particles, static_cast<long long>(r.steps), r.simulated_time, r.wall_seconds,
                 r.wall_seconds > 0 ? r.particles * static_cast<double>(r.steps) / r.wall_seconds : 0.0);
    for (const auto& [name, value] : r.errors) std::fprintf(stderr, "  %s = %.6g\n", name.c_str(), value);
    if (profile) {
      nlohmann::json j = ondine::kernel_profile_report();
      j["steps"] = r.steps;
      j["wall_seconds"] = r.wall_seconds;
      j["ranks"] = ranks;
      ondine::write_text_atomically(opt.out_dir + "/profile_kernels.json", j.dump(2) + "\n");
      std::fprintf(stderr, "ondine: kernel time %.3g s of %.3g s wall (%s/profile_kernels.json)", j["kernel_seconds"].get<double>(),
                   r.wall_seconds, opt.out_dir.c_str());
      if (j["groups"].contains("guard_interpolation"))
        std::fprintf(stderr, "; guard interpolation %.1f %%", 100 * j["groups"]["guard_interpolation"]["share"].get<double>());
      std::fprintf(stderr, "\n");
    }
    if (r.status == "interrupted")
      std::fprintf(stderr, "ondine: stopped by signal %d; continue with: ondine run %s --restart %s/checkpoint.h5\n", r.signal,
                   case_file.c_str(), opt.out_dir.c_str());
  }
  if (r.status == "diverged") return 3;
  if (r.status == "interrupted") return 128 + r.signal;
  return 0;
}

}  // namespace

// Thread binding: OpenMP reads OMP_PROC_BIND and OMP_PLACES when its runtime loads, before
// main, so the defaults are set by starting the program again with them. A user's setting
// of either variable always wins. One process: spread threads over the cores
// (OMP_PROC_BIND=spread, OMP_PLACES=threads), as `make run` does; under mpirun (Open MPI's
// OMPI_COMM_WORLD_SIZE > 1) the ranks share the cores and Open MPI binds each rank, so
// the threads are not bound again (OMP_PROC_BIND=false).
void default_thread_binding(char** argv) {
  if (std::getenv("OMP_PROC_BIND") || std::getenv("OMP_PLACES") || std::getenv("ONDINE_BINDING_SET")) return;
  const char* ranks = std::getenv("OMPI_COMM_WORLD_SIZE");
  const bool several = ranks && std::atoi(ranks) > 1;
  setenv("OMP_PROC_BIND", several ? "false" : "spread", 1);
  if (!several) setenv("OMP_PLACES", "threads", 1);
  setenv("ONDINE_BINDING_SET", "1", 1);  // no second restart, whatever happens
  execv("/proc/self/exe", argv);        // returns only on failure: go on unbound
}

int main(int argc, char** argv) {
  default_thread_binding(argv);
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  int ranks = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  int rc = 0;
  const std::string no_device = cuda_device_problem();
  if (no_device.empty()) {
    try {
      Kokkos::initialize(argc, argv);
    } catch (const std::exception& e) {  // a --kokkos-* option it cannot read
      std::string given;  // the arguments Kokkos reads (with or without their --kokkos- prefix)
      for (int k = 1; k < argc; ++k)
        for (const char* prefix : {"--kokkos", "--threads", "--num", "--device"})
          if (std::string(argv[k]).rfind(prefix, 0) == 0) given += std::string(given.empty() ? "" : " ") + argv[k];
      if (rank == 0)
        std::fprintf(stderr, "ondine: error: the Kokkos option%s %s cannot be used (%s); expected the forms `ondine --help` lists\n",
                     given.find(' ') != std::string::npos ? "s" : "", given.empty() ? "given" : given.c_str(), e.what());
      MPI_Finalize();
      return 2;
    }
  }
  try {
    rc = run_app(argc, argv, ranks, rank, no_device);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "ondine: error: %s\n", e.what());
    rc = 1;
    // a failure on one rank (a file only rank 0 writes, for one) leaves the others waiting in
    // a collective that never completes, and MPI_Finalize would wait for them: end every rank
    if (ranks > 1) {
      std::fflush(stderr);
      MPI_Abort(MPI_COMM_WORLD, rc);
    }
  }
  if (no_device.empty()) Kokkos::finalize();
  MPI_Finalize();
  return rc;
}
