#include "tools/fit/fit_pigment.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "materials/lobes/powder/pigment_table.h"
#include "materials/lobes/powder/powder_optics.h"
#include "spectra/input_error.h"
#include "spectra/named_spectra.h"
#include "spectra/tabulated_spectrum.h"

namespace ochre {

FitPigment FitPigment::named(const std::string& name) {
  const std::vector<std::string>& known = PigmentTable::names();
  if (std::find(known.begin(), known.end(), name) == known.end())
    throw InputError(
        fmt::format("--pigment: unknown pigment '{}' (built-in pigments: {})", name, fmt::join(known, ", ")));
  FitPigment p(named_spectrum("pigment-" + name + "-n"), named_spectrum("pigment-" + name + "-k"));
  p.name_ = name;
  return p;
}

FitPigment FitPigment::from_file(const std::filesystem::path& file) {
  try {
    FitPigment p(load_spectrum_csv(file, std::string_view("n")),
                 load_spectrum_csv(file, std::string_view("k")));
    p.file_ = file;
    return p;
  } catch (const std::exception& e) {
    throw InputError(fmt::format("--pigment-file: {}", e.what()));
  }
}

void FitPigment::check_index(double lambda_nm) const {
  const float lambda = static_cast<float>(lambda_nm);
  const double n = n_->eval(lambda), k = k_->eval(lambda);
  if (!(n > 0.0 && k >= 0.0))
    throw InputError(fmt::format("{}: the index at {} nm is n = {}, k = {}; need n > 0 and k >= 0",
                                 description(), lambda_nm, n, k));
}

double FitPigment::albedo(double lambda_nm, double radius_um) const {
  const float lambda = static_cast<float>(lambda_nm);
  return grain_albedo(n_->eval(lambda), k_->eval(lambda), radius_um, lambda_nm * 1e-3);
}

double FitPigment::tau_o(double lambda_nm) const {
  return powder_tau_o(n_->eval(static_cast<float>(lambda_nm)), PowderTau::kPaper);
}

std::string FitPigment::description() const {
  return file_.empty() ? "pigment " + name_ : "pigment file " + file_.string();
}

}  // namespace ochre
