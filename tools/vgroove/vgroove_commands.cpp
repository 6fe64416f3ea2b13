// ochre-vgroove bihemispherical, directional and tables (docs/tools.md).
#include "tools/vgroove/vgroove_commands.h"

#include <fmt/format.h>

#include <iostream>
#include <map>
#include <numbers>

#include "materials/core/pi.h"
#include "materials/lobes/vgroove/vgroove_reference.h"
#include "spectra/input_error.h"
#include "tools/cli/csv_columns.h"
#include "tools/vgroove/vgroove_inputs.h"
#include "tools/vgroove/vgroove_material.h"
#include "tools/vgroove/vgroove_spectral.h"
#include "tools/vgroove/vgroove_tables.h"
#include "tools/vgroove/vgroove_text_table.h"

namespace ochre {

namespace {

void check_quadrature(const char* option, int n) {
  if (n < 2 || n > 1024) throw InputError(fmt::format("{}: {} points is outside [2, 1024]", option, n));
}

void print(const TextTable& table, bool csv) {
  std::cout << (csv ? table.csv() : table.aligned());
}

double single_value(const char* option, const std::string& text) {
  const std::vector<double> values = parse_number_list(option, text);
  if (values.size() != 1) throw InputError(fmt::format("{}: give one value, not '{}'", option, text));
  return values[0];
}

// The paper's decimals: Tables 1 and 3 print reflectances in % to 0.1, Table 2 Delta E to 0.01. Ours
// gets one more decimal.
int printed_decimals(int table) {
  return table == 2 ? 2 : 1;
}

TextTable tables_csv(const std::vector<TableValue>& values) {
  TextTable t{{"table", "row", "alpha_deg", "ours", "printed", "difference"}, {}};
  for (const TableValue& v : values) {
    const int d = printed_decimals(v.table);
    t.rows.push_back({std::to_string(v.table), v.row, table_number(v.alpha_deg),
                      fmt::format("{:.{}f}", v.ours, d + 1), fmt::format("{:.{}f}", v.printed, d),
                      fmt::format("{:+.{}f}", v.ours - v.printed, d + 1)});
  }
  return t;
}

// One table laid out as the paper does (rows x dihedral angles), each row as three lines: ours, the
// printed value and the difference.
std::string tables_text(int table, const std::string& title, const std::vector<TableValue>& values) {
  std::vector<double> alphas;
  std::vector<std::string> rows;
  std::map<std::pair<std::string, double>, const TableValue*> cells;
  for (const TableValue& v : values) {
    if (std::find(alphas.begin(), alphas.end(), v.alpha_deg) == alphas.end()) alphas.push_back(v.alpha_deg);
    if (std::find(rows.begin(), rows.end(), v.row) == rows.end()) rows.push_back(v.row);
    cells[{v.row, v.alpha_deg}] = &v;
  }
  TextTable t{{"", ""}, {}};
  for (double a : alphas) t.header.push_back(table_number(a));
  const int d = printed_decimals(table);
  for (const std::string& row : rows) {
    std::vector<std::string> ours{row, "ours"}, printed{"", "printed"}, difference{"", "difference"};
    for (double a : alphas) {
      const auto it = cells.find({row, a});
      const TableValue* v = it == cells.end() ? nullptr : it->second;
      ours.push_back(v ? fmt::format("{:.{}f}", v->ours, d + 1) : "");
      printed.push_back(v ? fmt::format("{:.{}f}", v->printed, d) : "");
      difference.push_back(v ? fmt::format("{:+.{}f}", v->ours - v->printed, d + 1) : "");
    }
    t.rows.push_back(ours);
    t.rows.push_back(printed);
    t.rows.push_back(difference);
  }
  return fmt::format("Table {}: {}\n{}\n", table, title, t.aligned());
}

}  // namespace

int run_bihemispherical(const BihemisphericalArgs& args) {
  const VGrooveMaterial material = VGrooveMaterial::parse(args.material.name, args.material.ior);
  const std::vector<double> wavelengths = parse_number_list("--wavelength", args.wavelengths);
  check_wavelengths("--wavelength", wavelengths);
  const std::vector<double> alphas = parse_number_list("--alpha", args.alphas);
  check_alphas("--alpha", alphas);
  const std::vector<ChainModel> models = parse_models("--model", args.models);
  check_reflection_limit("--max-reflections", args.max_reflections);
  check_quadrature("--quadrature", args.quadrature);
  const std::vector<FacetIndex> facets = facets_at(material, wavelengths);
  TextTable t{{"material", "alpha_deg", "model", "wavelength_nm", "R"}, {}};
  for (double alpha : alphas)
    for (ChainModel model : models) {
      const std::vector<double> r = bihemispherical_reflectance(VGroove(alpha * kDegD), model, facets,
                                                                args.max_reflections, args.quadrature);
      for (size_t i = 0; i < wavelengths.size(); ++i)
        t.rows.push_back({material.label(), table_number(alpha), std::string(model_name(model)),
                          table_number(wavelengths[i]), fmt::format("{:.6f}", r[i])});
    }
  print(t, args.csv);
  return 0;
}

int run_directional(const DirectionalArgs& args) {
  const VGrooveMaterial material = VGrooveMaterial::parse(args.material.name, args.material.ior);
  const double wavelength = single_value("--wavelength", args.wavelength);
  check_wavelengths("--wavelength", {wavelength});
  const double alpha = single_value("--alpha", args.alpha);
  check_alphas("--alpha", {alpha});
  const std::vector<double> thetas = parse_number_list("--theta", args.thetas);
  check_thetas("--theta", thetas);
  const std::vector<double> phis = parse_number_list("--phi", args.phis);
  const std::vector<ChainModel> models = parse_models("--model", args.model);
  if (models.size() != 1) throw InputError(fmt::format("--model: give one model, not '{}'", args.model));
  check_reflection_limit("--max-reflections", args.max_reflections);
  const VGroove groove(alpha * kDegD);
  const std::vector<FacetIndex> facets{material.at(wavelength)};
  TextTable t{{"theta_deg", "phi_deg", "R", "max_reflections"}, {}};
  for (double theta : thetas)
    for (double phi : phis) {
      const DirectionalReflectance r = directional_reflectance(
          groove, groove_direction(theta * kDegD, phi * kDegD), models[0], facets, args.max_reflections);
      t.rows.push_back({table_number(theta), table_number(phi), fmt::format("{:.6f}", r.reflectance[0]),
                        std::to_string(r.max_reflections)});
    }
  print(t, args.csv);
  return 0;
}

int run_tables(const TablesArgs& args) {
  check_quadrature("--quadrature", args.quadrature);
  check_quadrature("--spectral-quadrature", args.spectral_quadrature);
  const std::vector<TableValue> t1 = paper_table1(args.quadrature);
  const std::vector<TableValue> t2 = paper_table2(args.spectral_quadrature);
  const std::vector<TableValue> t3 = paper_table3(args.quadrature);
  if (args.csv) {
    std::vector<TableValue> all = t1;
    all.insert(all.end(), t2.begin(), t2.end());
    all.insert(all.end(), t3.begin(), t3.end());
    print(tables_csv(all), true);
    return 0;
  }
  std::cout << tables_text(1, "bi-hemispherical reflectance (%) at 550 nm, rigorous model", t1)
            << tables_text(
                   2,
                   "CIE 1994 Delta E between the colours (D65) of the rigorous and unpolarized models "
                   "(\"Silicon (sp)\": rigorous and s/p)",
                   t2)
            << tables_text(3,
                           "silver (n = 0.1249 + 3.3391i) at 550 nm, reflectance (%) with rays limited to "
                           "1-4 reflections, rigorous model",
                           t3);
  return 0;
}

}  // namespace ochre
