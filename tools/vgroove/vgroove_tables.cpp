#include "tools/vgroove/vgroove_tables.h"

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include <numbers>

#include "materials/lobes/vgroove/vgroove_reference.h"
#include "spectra/cie94.h"
#include "tools/vgroove/vgroove_colour.h"
#include "tools/vgroove/vgroove_material.h"
#include "tools/vgroove/vgroove_printed_tables.h"
#include "tools/vgroove/vgroove_spectral.h"

namespace ochre {

namespace {

VGroove groove_deg(double alpha_deg) {
  return VGroove(alpha_deg * std::numbers::pi / 180.0);
}

// The materials of Table 1 in its row order.
const char* const kTable1Materials[] = {"glass", "Si", "Au", "paper-silver", "Cu", "Al"};

// The spectral reflectances of one material within a block of facets shared by one quadrature.
std::span<const double> block(const std::vector<double>& r, size_t index, size_t length) {
  return std::span<const double>(r).subspan(index * length, length);
}

}  // namespace

std::vector<TableValue> paper_table1(int quadrature_points) {
  std::vector<FacetIndex> facets;
  for (const char* name : kTable1Materials) facets.push_back(VGrooveMaterial::named(name).at(550.0));
  std::vector<std::vector<double>> by_alpha(kPaperTableAlphas.size());
  tbb::parallel_for(size_t{0}, by_alpha.size(), [&](size_t a) {
    by_alpha[a] = bihemispherical_reflectance(groove_deg(kPaperTableAlphas[a]), ChainModel::kRigorous, facets,
                                              0, quadrature_points);
  });
  std::vector<TableValue> values;
  for (size_t m = 0; m < facets.size(); ++m)
    for (size_t a = 0; a < by_alpha.size(); ++a) {
      const PrintedRow& printed = printed_table1()[m];
      values.push_back(
          {1, std::string(printed.name), kPaperTableAlphas[a], 100.0 * by_alpha[a][m], printed.values[a]});
    }
  return values;
}

std::vector<TableValue> paper_table2(int quadrature_points) {
  // Glass, gold, copper and silicon at the colour wavelengths, in one block of facets per model: the
  // geometry is shared by all of them. The s/p model is needed for silicon only.
  const char* const materials[] = {"glass", "Au", "Cu", "Si"};
  const size_t n = colour_wavelengths().size();
  std::vector<FacetIndex> all, silicon = facets_at(VGrooveMaterial::named("Si"), colour_wavelengths());
  for (const char* name : materials) {
    const std::vector<FacetIndex> f = facets_at(VGrooveMaterial::named(name), colour_wavelengths());
    all.insert(all.end(), f.begin(), f.end());
  }
  struct Job {
    ChainModel model;
    const std::vector<FacetIndex>* facets;
  };
  const Job jobs[] = {
      {ChainModel::kRigorous, &all}, {ChainModel::kUnpolarized, &all}, {ChainModel::kSeparateSP, &silicon}};
  constexpr size_t kJobs = std::size(jobs);
  std::vector<std::vector<double>> results(kPaperTableAlphas.size() * kJobs);
  tbb::parallel_for(size_t{0}, results.size(), [&](size_t i) {
    const Job& job = jobs[i % kJobs];
    results[i] = bihemispherical_reflectance(groove_deg(kPaperTableAlphas[i / kJobs]), job.model, *job.facets,
                                             0, quadrature_points);
  });
  std::vector<TableValue> values;
  for (size_t row = 0; row < printed_table2().size(); ++row) {
    const PrintedRow& printed = printed_table2()[row];
    const bool sp = row == std::size(materials);  // the last row: silicon, rigorous vs s/p
    for (size_t a = 0; a < kPaperTableAlphas.size(); ++a) {
      const std::vector<double>* r = &results[a * kJobs];
      const Lab rigorous = reflectance_to_lab(block(r[0], sp ? 3 : row, n));
      const Lab other = sp ? reflectance_to_lab(block(r[2], 0, n)) : reflectance_to_lab(block(r[1], row, n));
      values.push_back(
          {2, std::string(printed.name), kPaperTableAlphas[a], cie94(rigorous, other), printed.values[a]});
    }
  }
  return values;
}

std::vector<TableValue> paper_table3(int quadrature_points) {
  const std::vector<FacetIndex> silver{VGrooveMaterial::named("paper-silver").at(550.0)};
  struct Cell {
    int limit;
    size_t alpha_index;
    double printed, ours = 0.0;
  };
  std::vector<Cell> cells;
  for (int limit = 1; limit <= kPaperTable3MaxLimit; ++limit)
    for (size_t a = 0; a < kPaperTable3Alphas.size(); ++a)
      if (const std::optional<double> printed = printed_table3(limit, static_cast<int>(a)))
        cells.push_back({limit, a, *printed});
  tbb::parallel_for(size_t{0}, cells.size(), [&](size_t i) {
    Cell& c = cells[i];
    c.ours =
        100.0 * bihemispherical_reflectance(groove_deg(kPaperTable3Alphas[c.alpha_index]),
                                            ChainModel::kRigorous, silver, c.limit, quadrature_points)[0];
  });
  std::vector<TableValue> values;
  for (const Cell& c : cells)
    values.push_back({3, fmt::format("{} reflection{}", c.limit, c.limit == 1 ? "" : "s"),
                      kPaperTable3Alphas[c.alpha_index], c.ours, c.printed});
  return values;
}

}  // namespace ochre
