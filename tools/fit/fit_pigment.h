#pragma once
// The grains' optical constants n(lambda), k(lambda) as ochre-fit uses them: a built-in pigment of the
// powder node (`pigment`) or a CSV with columns n and k (`pigment_file`). The fit computes the grain
// albedo rho(lambda, b) by Lorenz-Mie and tau_o(lambda) by Eq 16 in double precision at each wavelength
// of the data (materials/lobes/powder/powder_optics.h): smooth in the radius, as finite differences need.
// The renderer interpolates the same quantities from a table (pigment_table.h), within 2e-4 of these.

#include <filesystem>
#include <string>

#include "spectra/spectrum.h"

namespace ochre {

class FitPigment {
 public:
  // Throws InputError naming --pigment and the known pigments.
  static FitPigment named(const std::string& name);
  // Throws InputError naming --pigment-file (missing file, no n or k column, bad values).
  static FitPigment from_file(const std::filesystem::path& file);

  // Throws InputError naming the pigment when its index at lambda_nm is not one Mie theory takes (n > 0,
  // k >= 0): a pigment file may hold anything.
  void check_index(double lambda_nm) const;
  double albedo(double lambda_nm, double radius_um) const;
  double tau_o(double lambda_nm) const;

  // "pigment hematite" or "pigment file nk.csv", for messages.
  std::string description() const;
  // The built-in name ("" for a file) and the file ("" for a built-in pigment).
  const std::string& name() const { return name_; }
  const std::filesystem::path& file() const { return file_; }

 private:
  FitPigment(SpectrumPtr n, SpectrumPtr k) : n_(std::move(n)), k_(std::move(k)) {}
  SpectrumPtr n_, k_;
  std::string name_;
  std::filesystem::path file_;
};

}  // namespace ochre
