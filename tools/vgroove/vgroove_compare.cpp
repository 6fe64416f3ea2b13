// ochre-vgroove compare (docs/tools.md): the same V-groove surface rendered three ways -- explicit groove
// geometry, the analytic `vgroove` closure, the explicit-profile `microgroove` closure -- under a constant
// white environment, each image's mean relative to the environment alone against the exact R(theta, phi)
// of materials/lobes/vgroove/vgroove_reference.h.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>
#include <numbers>
#include <optional>

#include "materials/core/pi.h"
#include "materials/lobes/vgroove/vgroove_reference.h"
#include "renderer/integrator/render.h"
#include "renderer/loader/scene_loader.h"
#include "renderer/util/atomic_file.h"
#include "spectra/input_error.h"
#include "tools/cli/csv_columns.h"
#include "tools/vgroove/vgroove_commands.h"
#include "tools/vgroove/vgroove_compare_scene.h"
#include "tools/vgroove/vgroove_inputs.h"
#include "tools/vgroove/vgroove_material.h"
#include "tools/vgroove/vgroove_scratch_dir.h"
#include "tools/vgroove/vgroove_text_table.h"

namespace ochre {

namespace {

namespace fs = std::filesystem;

// The facets' index is each material's at this wavelength, used at every wavelength: a spectrally flat
// surface, whose image relative to the environment's is R exactly whatever wavelengths are sampled.
constexpr double kWavelength = 550.0;
constexpr double kMaxTheta = 85.0;  // grazing views need plates of many grooves (compare_scene)

struct Surface {
  GrooveSurface kind;
  const char* name;
};
constexpr Surface kSurfaces[] = {{GrooveSurface::kExplicit, "explicit"},
                                 {GrooveSurface::kAnalytic, "analytic"},
                                 {GrooveSurface::kMicrogroove, "microgroove"}};

// Per-pixel luminance (each pixel the mean of its samples) and the render's wall-clock time.
struct Rendered {
  std::vector<double> y;
  double seconds = 0;
};

Rendered render_scene_file(const fs::path& file) {
  const LoadedScene loaded = load_scene(file);
  Film film(loaded.job.settings.width, loaded.job.settings.height);
  const RenderStats stats = render(*loaded.scene, loaded.job, film);
  Rendered r{{}, stats.seconds};
  for (int j = 0; j < film.height(); ++j)
    for (int i = 0; i < film.width(); ++i) r.y.push_back(film.mean(i, j).y);
  return r;
}

double mean_of(const std::vector<double>& v) {
  double sum = 0;
  for (double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

// The image mean relative to the environment's mean, and its standard error from the spread of the
// pixel values (each an average of spp samples).
struct Estimate {
  double value = 0, standard_error = 0, seconds = 0;
};

Estimate relative_to_environment(const Rendered& image, double environment_mean) {
  const double n = static_cast<double>(image.y.size()), mean = mean_of(image.y);
  double squares = 0;
  for (double y : image.y) squares += (y - mean) * (y - mean);
  const double variance = squares / (n - 1);
  return {mean / environment_mean, std::sqrt(variance / n) / environment_mean, image.seconds};
}

struct Row {
  std::string material;
  double alpha_deg, theta_deg, phi_deg, exact;
  Estimate estimates[3];  // in kSurfaces order
};

// Seven significant digits: a glass groove at normal incidence reflects 1e-6.
std::string reflectance(double r) {
  return fmt::format("{:.7g}", r);
}

std::vector<std::string> row_fields(const Row& r) {
  std::vector<std::string> fields{r.material, table_number(r.alpha_deg), table_number(r.theta_deg),
                                  table_number(r.phi_deg), reflectance(r.exact)};
  for (const Estimate& e : r.estimates) {
    fields.push_back(reflectance(e.value));
    fields.push_back(fmt::format("{:.3e}", e.standard_error));
    fields.push_back(fmt::format("{:.4g}", e.seconds));
  }
  return fields;
}

std::string csv_line(const std::vector<std::string>& fields) {
  return fmt::format("{}\n", fmt::join(fields, ","));
}

std::vector<std::string> header() {
  std::vector<std::string> h{"material", "alpha_deg", "theta_deg", "phi_deg", "exact"};
  for (const Surface& s : kSurfaces)
    for (const char* suffix : {"", "_se", "_seconds"}) h.push_back(std::string(s.name) + suffix);
  return h;
}

// |rendered - exact| in standard errors (infinite for a wrong value with no spread).
double deviation(const Estimate& e, double exact) {
  const double diff = std::abs(e.value - exact);
  if (e.standard_error > 0) return diff / e.standard_error;
  return diff == 0 ? 0 : std::numeric_limits<double>::infinity();
}

std::string summary(const std::vector<Row>& rows) {
  std::string text = fmt::format("summary over {} views:\n", rows.size());
  double seconds[3] = {0, 0, 0};
  for (size_t s = 0; s < 3; ++s) {
    double worst = 0, worst_diff = 0;
    const Row* where = &rows.front();
    for (const Row& r : rows) {
      seconds[s] += r.estimates[s].seconds;
      worst_diff = std::max(worst_diff, std::abs(r.estimates[s].value - r.exact));
      if (deviation(r.estimates[s], r.exact) >= worst) {
        worst = deviation(r.estimates[s], r.exact);
        where = &r;
      }
    }
    text += fmt::format(
        "  {:<12} max |diff|/SE {:6.2f} ({} alpha {} theta {} phi {}), max |diff| {:.2e}, {:.2f} s\n",
        kSurfaces[s].name, worst, where->material, table_number(where->alpha_deg),
        table_number(where->theta_deg), table_number(where->phi_deg), worst_diff, seconds[s]);
  }
  double ratio_sum = 0;
  for (const Row& r : rows) ratio_sum += r.estimates[0].seconds / r.estimates[1].seconds;
  text += fmt::format(
      "  time explicit/analytic: mean {:.3f} per view, {:.3f} in total; microgroove/analytic {:.3f} in "
      "total\n",
      ratio_sum / static_cast<double>(rows.size()), seconds[0] / seconds[1], seconds[2] / seconds[1]);
  return text;
}

std::string facets_note(const std::vector<VGrooveMaterial>& materials) {
  std::string text =
      fmt::format("facet indices, constant at every wavelength (each material's at {} nm):", kWavelength);
  for (const VGrooveMaterial& m : materials) {
    const FacetIndex f = m.at(kWavelength);
    text += f.mirror ? fmt::format(" {} ideal mirror;", m.label())
                     : fmt::format(" {} n = {:.4f}, k = {:.4f};", m.label(), f.eta.real(), -f.eta.imag());
  }
  text.back() = '\n';
  return text;
}

struct CompareInputs {
  std::vector<VGrooveMaterial> materials;
  std::vector<double> alphas, thetas, phis;
};

CompareInputs parse_inputs(const CompareArgs& args) {
  CompareInputs in{VGrooveMaterial::parse_list(args.material.name, args.material.ior),
                   parse_number_list("--alpha", args.alphas), parse_number_list("--theta", args.thetas),
                   parse_number_list("--phi", args.phis)};
  for (double a : in.alphas)
    if (!(a >= 1.0 && a <= 179.9))
      throw InputError(
          fmt::format("--alpha: dihedral angle {} is outside [1, 179.9] degrees (the grooves of the "
                      "explicit plate and of microgroove)",
                      a));
  for (double t : in.thetas)
    if (!(t >= 0.0 && t <= kMaxTheta))
      throw InputError(
          fmt::format("--theta: polar angle {} is outside [0, {}] degrees (grazing views need "
                      "plates of too many grooves)",
                      t, kMaxTheta));
  if (args.spp < 1 || args.spp > (1 << 24))
    throw InputError(fmt::format("--spp: {} is outside [1, {}]", args.spp, 1 << 24));
  if (args.resolution < 2 || args.resolution > 4096)
    throw InputError(fmt::format("--resolution: {} pixels is outside [2, 4096]", args.resolution));
  if (args.threads < 0)
    throw InputError(fmt::format("--threads: {} is negative (0 = all cores)", args.threads));
  if (!args.scene_dir.empty() && !fs::is_directory(args.scene_dir))
    throw InputError(fmt::format("--scene-dir: {} is not a directory", args.scene_dir));
  return in;
}

// Writes DIR/NAME.json, NAME made of letters, digits, '.', '-' and '_' ("n=1.5 k=0" -> "n_1.5_k_0").
fs::path write_scene(const fs::path& dir, std::string name, const std::string& text) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-') c = '_';
  const fs::path file = dir / (name + ".json");
  write_text_file(file, text);
  return file;
}

}  // namespace

int run_compare(const CompareArgs& args) {
  const CompareInputs in = parse_inputs(args);
  std::optional<ScratchDir> scratch;
  if (args.scene_dir.empty()) scratch.emplace(fs::temp_directory_path() / "ochre-vgroove-compare");
  const fs::path dir = scratch ? scratch->path() : fs::path(args.scene_dir);

  CompareView view;
  view.resolution = args.resolution;
  view.spp = args.spp;
  view.threads = args.threads;
  view.seed = args.seed;
  const double environment_mean =
      mean_of(render_scene_file(write_scene(dir, "environment", environment_scene_json(view))).y);

  std::ostream& notes = args.csv ? std::cerr : std::cout;
  notes << facets_note(in.materials);
  if (args.csv) std::cout << csv_line(header()) << std::flush;
  std::vector<Row> rows;
  for (const VGrooveMaterial& material : in.materials)
    for (double alpha : in.alphas)
      for (double theta : in.thetas)
        for (double phi : in.phis) {
          view.facet = material.at(kWavelength);
          view.alpha_deg = alpha;
          view.theta_deg = theta;
          view.phi_deg = phi;
          const std::vector<FacetIndex> facets{view.facet};
          Row row{
              material.label(),
              alpha,
              theta,
              phi,
              directional_reflectance(VGroove(alpha * kDegD), groove_direction(theta * kDegD, phi * kDegD),
                                      ChainModel::kRigorous, facets)
                  .reflectance[0],
              {}};
          for (size_t s = 0; s < 3; ++s) {
            const std::string name =
                fmt::format("{}_alpha{}_theta{}_phi{}_{}", material.label(), table_number(alpha),
                            table_number(theta), table_number(phi), kSurfaces[s].name);
            const fs::path file = write_scene(dir, name, compare_scene_json(kSurfaces[s].kind, view));
            row.estimates[s] = relative_to_environment(render_scene_file(file), environment_mean);
          }
          if (args.csv) std::cout << csv_line(row_fields(row)) << std::flush;
          rows.push_back(row);
        }
  if (!args.csv) {
    TextTable table{header(), {}};
    for (const Row& r : rows) table.rows.push_back(row_fields(r));
    std::cout << table.aligned();
  }
  notes << summary(rows);
  return 0;
}

}  // namespace ochre
