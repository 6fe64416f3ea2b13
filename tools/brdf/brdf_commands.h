#pragma once
// The subcommands of ochre-brdf, the material explorer (docs/tools.md). Each returns the exit code
// (docs/cli.md, "Exit codes"; tools/cli/program.h): 0 = done (chi2: every incidence passed), 4 = chi2
// rejected a sampler, 1 = the plot script failed; bad input throws InputError or GraphError (run_program
// prints it and exits with 2). Output files are written under a temporary name
// and renamed when complete, so a failure leaves no partial file; an output that is one of the files
// read (the material, a texture, the input CSV, ...), a link, a device or a FIFO is refused
// (renderer/output/output_files.h).

#include <cstdint>
#include <string>
#include <vector>

namespace ochre {

struct MaterialArgs {
  std::string file;  // MAT.json
  std::string name;  // material to pick from a "materials" object (empty: the only one)
};

struct EvalArgs {
  MaterialArgs material;
  std::string input, output;
};

struct AlbedoArgs {
  MaterialArgs material;
  float lambda_nm = 550.0f;
  std::vector<double> angles_deg{0, 10, 20, 30, 40, 50, 60, 70, 80, 85, 89};
  uint64_t samples = 200'000;
  uint64_t seed = 1;
  std::string output;  // empty: standard output
};

struct PlotArgs {
  MaterialArgs material;
  std::string output;  // PNG
  std::string csv;     // optional: keep the plotted values
  std::vector<double> incidence_deg{0, 30, 60};
  float lambda_nm = 550.0f;
};

struct Chi2Args {
  MaterialArgs material;
  std::vector<double> incidence_deg{0, 30, 60, 85};
  float lambda_nm = 550.0f;
  int samples = 1'000'000;
  double alpha = 0.01;  // overall significance, split over the incidences (Sidak)
  uint64_t seed = 1;
  std::string output;  // empty: standard output
};

int run_eval(const EvalArgs& args);
int run_albedo(const AlbedoArgs& args);
int run_plot(const PlotArgs& args);
int run_chi2(const Chi2Args& args);

}  // namespace ochre
