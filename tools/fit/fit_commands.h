#pragma once
// The commands of ochre-fit (docs/tools.md). Each returns the exit code (docs/cli.md, "Exit codes";
// tools/cli/program.h): 0 done, 1 the plot script failed (nothing written); bad input throws InputError
// (run_program prints it and exits with 2).

#include <cstdint>
#include <string>
#include <vector>

namespace ochre {

struct PigmentArgs {
  std::string name = "hematite";  // --pigment
  std::string file;               // --pigment-file (replaces the name)
};

struct PowderFitArgs {
  std::string data;  // measurements CSV
  PigmentArgs pigment;
  std::vector<std::string> fix;     // NAME=VALUE
  std::vector<std::string> start;   // NAME=VALUE
  std::vector<std::string> bounds;  // NAME=LOWER:UPPER
  double max_theta_i = 90.0;        // degrees; measurements with a larger theta_i are left out
  std::string residuals = "relative";
  std::string material, plot, csv;  // outputs (empty: not written)
  bool quiet = false;               // no progress lines
};

struct PowderSynthesizeArgs {
  std::string output;
  PigmentArgs pigment;
  std::vector<std::string> params;  // NAME=VALUE, the others at the powder node's defaults
  std::vector<double> lambdas_nm{450.0, 550.0, 650.0};
  std::string geometry;  // measurements whose geometries and wavelengths replace the built-in grid
  double noise = 0.01;
  uint64_t seed = 1;
};

int run_powder_fit(const PowderFitArgs& args);
int run_powder_synthesize(const PowderSynthesizeArgs& args);

}  // namespace ochre
