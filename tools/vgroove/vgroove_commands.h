#pragma once
// The subcommands of ochre-vgroove (docs/tools.md): the V-groove model of Saint-Pierre, Chavel,
// Simonot and Hebert 2019 (materials/lobes/vgroove/) as numbers, tables and figures. Each returns the
// exit code (docs/cli.md, "Exit codes"; tools/cli/program.h: 0 done, 1 a plot script failed); bad input
// throws InputError (run_program prints it and exits with 2). Output files follow docs/cli.md, "Output
// files": checked before any work (renderer/output/output_files.h), written under temporary names and renamed
// together when all are complete (renderer/util/output_transaction.h).

#include <string>

namespace ochre {

struct MaterialOption {
  std::string name;  // --material (maps: a comma list)
  std::string ior;   // --ior n,k
};

struct BihemisphericalArgs {
  MaterialOption material;
  std::string wavelengths = "550", alphas, models = "rigorous";
  int max_reflections = 0;  // 0 = no limit
  int quadrature = 96;
  bool csv = false;
};

struct DirectionalArgs {
  MaterialOption material;
  std::string wavelength = "550", alpha, thetas, phis, model = "rigorous";
  int max_reflections = 0;
  bool csv = false;
};

struct TablesArgs {
  int quadrature = 96;           // Tables 1 and 3
  int spectral_quadrature = 32;  // Table 2 (36 wavelengths x 4 materials x 3 models)
  bool csv = false;
};

struct MapsArgs {
  MaterialOption material;
  std::string alphas, models = "rigorous";
  int size = 256;
  std::string output, counts;
  bool grid = false;  // a labelled figure (tools/scripts/plot_vgroove.py); implied by several panels
};

struct ProfileArgs {
  MaterialOption material;
  std::string alpha, models = "rigorous,unpolarized,sp";
  double step = 0.5;  // degrees of theta
  std::string output, png;
};

struct CompareArgs {
  MaterialOption material;  // facets: each material's index at 550 nm, as a constant
  std::string alphas = "45", thetas = "10,30,50,70", phis = "0,30,60,90,135";
  int spp = 64, resolution = 64, threads = 0;
  unsigned long long seed = 0;
  std::string scene_dir;  // keep the scenes there (else a temporary directory)
  bool csv = false;
};

int run_bihemispherical(const BihemisphericalArgs& args);
int run_directional(const DirectionalArgs& args);
int run_tables(const TablesArgs& args);
int run_maps(const MapsArgs& args);
int run_profile(const ProfileArgs& args);
// Renders explicit grooves and the two closures against the exact R (renderer/integrator/render.h).
int run_compare(const CompareArgs& args);

}  // namespace ochre
