// ochre-vgroove: the V-groove model of Saint-Pierre, Chavel, Simonot and Hebert 2019 ("Angular
// reflectance model for ridged specular surfaces, with comprehensive calculation of inter-reflections
// and polarization", JOSA A 36(11), C51) as numbers, the paper's tables and its figures
// (docs/tools.md).
//   ochre-vgroove bihemispherical --material NAME|--ior n,k --alpha LIST [--wavelength LIST] [--model LIST]
//   ochre-vgroove directional     --material NAME|--ior n,k --alpha A --theta LIST --phi LIST [...]
//   ochre-vgroove tables          [--csv]
//   ochre-vgroove maps            --material NAMES|--ior n,k --alpha LIST --size PX -o OUT.png [...]
//   ochre-vgroove profile         --material NAME|--ior n,k --alpha A -o OUT.csv [--png OUT.png]
//   ochre-vgroove compare         --material NAMES|--ior n,k [--alpha LIST] [--theta LIST] [--phi LIST]
//                                 [--spp N] [--resolution PX] [--seed S] [--threads N] [--scene-dir DIR]
// Exit codes (docs/cli.md, "Exit codes"): 0 = done, 2 = bad input or usage, 1 = a plot script failed, or an
// internal error.
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "ochre/version.h"
#include "renderer/util/signal_cleanup.h"
#include "tools/cli/command_line.h"
#include "tools/cli/program.h"
#include "tools/vgroove/vgroove_commands.h"

namespace {

constexpr const char* kModelHelp = "rigorous | unpolarized | sp | paper_literal";

void add_material(CLI::App& command, ochre::MaterialOption& material, const char* names_help) {
  command.add_option("--material", material.name, names_help);
  command.add_option("--ior", material.ior, "Facet index n + i k as n,k (k >= 0), at every wavelength");
}

constexpr const char* kMaterialHelp =
    "Au | Ag | Cu | Al | Si (built-in data), glass (n 1.5), paper-silver "
    "(0.1249 + 3.3391i), mirror";

int vgroove_command(int argc, char** argv) {
  CLI::App app{"ochre-vgroove: the V-groove model of Saint-Pierre et al. 2019 (JOSA A 36(11) C51)"};
  app.set_version_flag("--version", "ochre-vgroove " OCHRE_VERSION);
  app.require_subcommand(1);

  ochre::BihemisphericalArgs bi;
  CLI::App* bi_cmd = app.add_subcommand("bihemispherical", "Bi-hemispherical reflectance (Eq 42)");
  add_material(*bi_cmd, bi.material, kMaterialHelp);
  bi_cmd->add_option("--wavelength", bi.wavelengths, "Wavelengths (nm), comma list")->capture_default_str();
  bi_cmd->add_option("--alpha", bi.alphas, "Dihedral angles (degrees, (0, 180]), comma list")->required();
  bi_cmd->add_option("--model", bi.models, kModelHelp)->capture_default_str();
  bi_cmd->add_option("--max-reflections", bi.max_reflections, "Discard rays with more reflections (0 = none)")
      ->capture_default_str();
  bi_cmd->add_option("--quadrature", bi.quadrature, "Gauss-Legendre points per axis")->capture_default_str();
  bi_cmd->add_flag("--csv", bi.csv, "CSV instead of aligned text");

  ochre::DirectionalArgs dir;
  CLI::App* dir_cmd =
      app.add_subcommand("directional", "Hemispherical-directional reflectance R(theta, phi) (Eq 36)");
  add_material(*dir_cmd, dir.material, kMaterialHelp);
  dir_cmd->add_option("--wavelength", dir.wavelength, "Wavelength (nm)")->capture_default_str();
  dir_cmd->add_option("--alpha", dir.alpha, "Dihedral angle (degrees)")->required();
  dir_cmd->add_option("--theta", dir.thetas, "Polar angles (degrees, [0, 90)), comma list")->required();
  dir_cmd->add_option("--phi", dir.phis, "Azimuths (degrees from the axis across the grooves), comma list")
      ->required();
  dir_cmd->add_option("--model", dir.model, kModelHelp)->capture_default_str();
  dir_cmd
      ->add_option("--max-reflections", dir.max_reflections, "Discard rays with more reflections (0 = none)")
      ->capture_default_str();
  dir_cmd->add_flag("--csv", dir.csv, "CSV instead of aligned text");

  ochre::TablesArgs tables;
  CLI::App* tables_cmd =
      app.add_subcommand("tables", "The paper's Tables 1-3, ours beside the printed values");
  tables_cmd->add_option("--quadrature", tables.quadrature, "Gauss-Legendre points per axis, Tables 1 and 3")
      ->capture_default_str();
  tables_cmd->add_option("--spectral-quadrature", tables.spectral_quadrature, "The same for Table 2")
      ->capture_default_str();
  tables_cmd->add_flag("--csv", tables.csv, "CSV: table,row,alpha_deg,ours,printed,difference");

  ochre::MapsArgs maps;
  CLI::App* maps_cmd =
      app.add_subcommand("maps", "Colour and reflection-count maps (Lambert equal-area, Eq 38)");
  add_material(*maps_cmd, maps.material, "Comma list of: Au, Ag, Cu, Al, Si, glass, paper-silver, mirror");
  maps_cmd->add_option("--alpha", maps.alphas, "Dihedral angles (degrees), comma list")->required();
  maps_cmd->add_option("--model", maps.models, "Comma list of models")->capture_default_str();
  maps_cmd->add_option("--size", maps.size, "Map width and height (pixels)")->capture_default_str();
  maps_cmd->add_option("-o,--output", maps.output, "Colour map PNG")
      ->required()
      ->check(ochre::non_empty_path());
  maps_cmd->add_option("--counts", maps.counts, "Also write the reflection-count map (PNG)")
      ->check(ochre::non_empty_path());
  maps_cmd->add_flag("--grid", maps.grid, "Labelled figure (implied by several materials, alphas or models)");

  ochre::ProfileArgs profile;
  CLI::App* profile_cmd = app.add_subcommand("profile", "L* versus theta at phi = 0 and 90 degrees (Fig 9)");
  add_material(*profile_cmd, profile.material, kMaterialHelp);
  profile_cmd->add_option("--alpha", profile.alpha, "Dihedral angle (degrees)")->required();
  profile_cmd->add_option("--model", profile.models, "Comma list of models")->capture_default_str();
  profile_cmd->add_option("--step", profile.step, "Theta step (degrees)")->capture_default_str();
  profile_cmd->add_option("-o,--output", profile.output, "CSV: phi_deg,theta_deg,model,L")
      ->required()
      ->check(ochre::non_empty_path());
  profile_cmd->add_option("--png", profile.png, "Also plot it (PNG, needs matplotlib)")
      ->check(ochre::non_empty_path());

  ochre::CompareArgs compare;
  CLI::App* compare_cmd = app.add_subcommand(
      "compare", "Render explicit grooves, vgroove and microgroove against the exact R(theta, phi)");
  add_material(*compare_cmd, compare.material,
               "Comma list of: Au, Ag, Cu, Al, Si, glass, paper-silver, mirror (index at 550 nm)");
  compare_cmd->add_option("--alpha", compare.alphas, "Dihedral angles (degrees, [1, 179.9]), comma list")
      ->capture_default_str();
  compare_cmd
      ->add_option("--theta", compare.thetas, "Polar angles of the views (degrees, [0, 85]), comma list")
      ->capture_default_str();
  compare_cmd
      ->add_option("--phi", compare.phis, "Azimuths (degrees from the axis across the grooves), comma list")
      ->capture_default_str();
  compare_cmd->add_option("--spp", compare.spp, "Samples per pixel")->capture_default_str();
  compare_cmd->add_option("--resolution", compare.resolution, "Film width and height (pixels)")
      ->capture_default_str();
  compare_cmd->add_option("--seed", compare.seed, "Sampler seed")
      ->capture_default_str()
      ->check(ochre::unsigned_64_check());
  compare_cmd->add_option("--threads", compare.threads, "Render threads (0 = all cores)")
      ->capture_default_str();
  compare_cmd->add_option("--scene-dir", compare.scene_dir, "Keep the scenes rendered in this directory")
      ->check(ochre::non_empty_path());
  compare_cmd->add_flag("--csv", compare.csv, "CSV instead of aligned text (notes and summary on stderr)");

  if (!ochre::parse_command_line(app, argc, argv)) return ochre::kExitDone;  // --help, --version
  ochre::install_signal_cleanup();  // SIGINT / SIGTERM leave no temporary output or scratch directory
  if (*bi_cmd) return ochre::run_bihemispherical(bi);
  if (*dir_cmd) return ochre::run_directional(dir);
  if (*tables_cmd) return ochre::run_tables(tables);
  if (*maps_cmd) return ochre::run_maps(maps);
  if (*profile_cmd) return ochre::run_profile(profile);
  return ochre::run_compare(compare);
}

}  // namespace

int main(int argc, char** argv) {
  return ochre::run_program("ochre-vgroove", [&] { return vgroove_command(argc, argv); });
}
