// ochre-halfspace: Monte-Carlo BRDF of a half-space of Lambertian spheres (docs/tools.md).
//   ochre-halfspace [--c 0.3,0.8,0.99,1] [--mu 0.1,0.2,0.4,0.6,0.8,1] [--phi 0,45,90,135,180]
//                   [--paths N] [--seed S] [--threads T] [--max-collisions M] [--phase ls|isotropic]
//                   [--output FILE.csv]
// For each c and each mu_i, one batch of random walks scores every (mu_o, phi) of the grid at once.
// Writes CSV rows c,mu_i,mu_o,phi_deg,f_single,f_single_se,f_multiple,f_multiple_se,f_total,f_total_se
// after '#' comment lines holding the command that regenerates the file and each batch's albedo.
// Exit codes (docs/cli.md, "Exit codes"): 0 = done, 2 = bad input or usage, 1 = internal error. The
// simulation (halfspace_mc.h) is standard library only; the command line uses ochre's shared one
// (tools/cli).
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "ochre/version.h"
#include "renderer/util/atomic_file.h"
#include "renderer/util/signal_cleanup.h"
#include "spectra/input_error.h"
#include "tools/cli/command_line.h"
#include "tools/cli/program.h"
#include "tools/halfspace/halfspace_mc.h"

namespace {

namespace hs = ochre::halfspace;
namespace fs = std::filesystem;
using ochre::InputError;

struct HalfspaceCommand {
  std::vector<double> c{0.3, 0.8, 0.99, 1.0};
  std::vector<double> mu{0.1, 0.2, 0.4, 0.6, 0.8, 1.0};
  std::vector<double> phi_deg{0, 45, 90, 135, 180};
  uint64_t paths = 100'000;
  uint64_t seed = 1;
  unsigned threads = 1;
  uint64_t max_collisions = 1'000'000;
  std::string phase = "ls";
  std::string output;
};

std::string format_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.9g", x);
  return buffer;
}

void check_grid(const HalfspaceCommand& cmd) {
  for (double c : cmd.c)
    if (!(c >= 0.0 && c <= 1.0)) throw InputError("--c values must be in [0, 1], got " + format_number(c));
  for (double mu : cmd.mu)
    if (!(mu > 0.0 && mu <= 1.0)) throw InputError("--mu values must be in (0, 1], got " + format_number(mu));
  for (double phi : cmd.phi_deg)
    if (!std::isfinite(phi)) throw InputError("--phi values must be finite, got " + format_number(phi));
  if (cmd.paths == 0) throw InputError("--paths must be positive");
  if (cmd.max_collisions == 0) throw InputError("--max-collisions must be positive");
}

// The grid's outgoing directions for wi at phi = 0, in (mu_o, phi) row order.
std::vector<hs::Direction> outgoing_grid(const HalfspaceCommand& cmd) {
  std::vector<hs::Direction> out;
  for (double mu_o : cmd.mu)
    for (double phi : cmd.phi_deg)
      out.push_back(hs::direction_from_angles(mu_o, phi * std::numbers::pi / 180.0));
  return out;
}

void write_row(std::ostream& out, double c, double mu_i, double mu_o, double phi,
               const hs::HalfspaceResult& r) {
  out << format_number(c) << ',' << format_number(mu_i) << ',' << format_number(mu_o) << ','
      << format_number(phi);
  for (const hs::Estimate* e : {&r.single, &r.multiple, &r.total})
    out << ',' << format_number(e->mean) << ',' << format_number(e->standard_error);
  out << '\n';
}

int run(const HalfspaceCommand& cmd, const std::string& command_line) {
  check_grid(cmd);
  // The output is checked before the simulation (a directory, a link, a device: refused with nothing done).
  if (!cmd.output.empty()) ochre::check_output_writable(fs::path(cmd.output));
  ochre::install_signal_cleanup();
  hs::SimulationOptions options;
  options.threads = cmd.threads;
  options.max_collisions = cmd.max_collisions;
  if (cmd.phase == "isotropic")
    options.phase = hs::PhaseFunction::kIsotropic;
  else if (cmd.phase != "ls")
    throw InputError("--phase must be 'ls' or 'isotropic', got '" + cmd.phase + "'");

  const std::vector<hs::Direction> outgoing = outgoing_grid(cmd);
  std::ostringstream comments, rows;
  comments << "# ochre-halfspace: Monte-Carlo BRDF (1/sr, no cosine) of a half-space with the "
           << (cmd.phase == "ls" ? "Lambertian-sphere (d'Eon Eq 1)" : "isotropic") << " phase function\n"
           << "# regenerate (from the repository root, after building): build/bin/" << command_line << "\n"
           << "# columns: BRDF f(wi, wo) for wi at mu_i, wo at mu_o and relative azimuth phi_deg (0 = "
              "backscatter\n"
           << "# side); single = first collision, multiple = the rest, total = both; _se = standard error\n";
  rows << "c,mu_i,mu_o,phi_deg,f_single,f_single_se,f_multiple,f_multiple_se,f_total,f_total_se\n";
  uint64_t batch = 0;
  for (double c : cmd.c) {
    for (double mu_i : cmd.mu) {
      const auto start = std::chrono::steady_clock::now();
      const hs::GridResult r = hs::simulate_brdf_grid(c, hs::direction_from_angles(mu_i, 0.0), outgoing,
                                                      cmd.paths, cmd.seed + batch++, options);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      std::ostringstream summary;
      summary << "c=" << format_number(c) << " mu_i=" << format_number(mu_i) << ": " << r.paths
              << " paths, albedo " << format_number(r.albedo.mean) << " +- "
              << format_number(r.albedo.standard_error) << ", truncated weight "
              << format_number(r.truncated_weight) << ", " << format_number(double(r.collisions) / r.paths)
              << " collisions/path";
      comments << "# " << summary.str() << '\n';  // no timing here: the file depends on the command only
      std::cerr << "ochre-halfspace: " << summary.str() << ", " << format_number(seconds) << " s\n";
      size_t k = 0;
      for (double mu_o : cmd.mu)
        for (double phi : cmd.phi_deg) write_row(rows, c, mu_i, mu_o, phi, r.brdf[k++]);
    }
  }
  if (cmd.output.empty()) {
    std::cout << comments.str() << rows.str();
    return 0;
  }
  // Written under a temporary name and renamed, as every output of ochre (docs/cli.md, "Output files").
  ochre::write_text_file(fs::path(cmd.output), comments.str() + rows.str());
  return ochre::kExitDone;
}

int halfspace_command(int argc, char** argv) {
  CLI::App app{"ochre-halfspace: Monte-Carlo reference BRDF of a half-space of Lambertian spheres"};
  app.set_version_flag("--version", "ochre-halfspace " OCHRE_VERSION);
  HalfspaceCommand cmd;
  app.add_option("--c", cmd.c, "Single-scattering albedos")->delimiter(',')->capture_default_str();
  app.add_option("--mu", cmd.mu, "Cosines used for both mu_i and mu_o")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--phi", cmd.phi_deg, "Relative azimuths in degrees (0 = backscatter side)")
      ->delimiter(',')
      ->capture_default_str();
  app.add_option("--paths", cmd.paths, "Random walks per (c, mu_i)")
      ->capture_default_str()
      ->check(ochre::unsigned_64_check());
  app.add_option("--seed", cmd.seed, "Seed (batch k uses seed + k)")
      ->capture_default_str()
      ->check(ochre::unsigned_64_check());
  app.add_option("--threads", cmd.threads, "Threads (0 = all cores); results do not depend on it")
      ->capture_default_str();
  app.add_option("--max-collisions", cmd.max_collisions, "Walks are cut after this many collisions")
      ->capture_default_str()
      ->check(ochre::unsigned_64_check());
  app.add_option("--phase", cmd.phase, "Phase function: ls (Lambertian sphere) or isotropic")
      ->capture_default_str();
  app.add_option("--output", cmd.output, "CSV file (default: standard output)");
  if (!ochre::parse_command_line(app, argc, argv)) return ochre::kExitDone;  // --help, --version
  std::string command_line = "ochre-halfspace";
  for (int i = 1; i < argc; ++i) command_line += std::string(" ") + argv[i];
  return run(cmd, command_line);
}

}  // namespace

int main(int argc, char** argv) {
  return ochre::run_program("ochre-halfspace", [&] { return halfspace_command(argc, argv); });
}
