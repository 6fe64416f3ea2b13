// The committed Monte-Carlo reference table tests/data/halfspace_reference.csv (written by
// ochre-halfspace, the command is in its header): its single-scattering column must match the closed
// form (d'Eon Eq 17) and its totals must be reciprocal, within the table's own standard errors, so a
// table from a broken or stale simulation cannot be committed unnoticed.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "support/test_paths.h"
#include "tools/halfspace/direction.h"
#include "tools/halfspace/phase_function.h"

namespace ochre::halfspace::test::reference_table_test {
namespace {

// With ~1000 rows, 4.5 sigma keeps the chance of a false alarm of a correct table below 1 %.
constexpr double kSigmas = 4.5;

struct Row {
  double c, mu_i, mu_o, phi_deg, single, single_se, multiple, multiple_se, total, total_se;
};

struct Table {
  std::vector<std::string> comments;
  std::string header;
  std::vector<Row> rows;
};

Table read_table() {
  std::ifstream in(ochre::test::source_dir() / "tests/data/halfspace_reference.csv");
  Table t;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    if (line[0] == '#') {
      t.comments.push_back(line);
    } else if (t.header.empty()) {
      t.header = line;
    } else {
      std::replace(line.begin(), line.end(), ',', ' ');
      std::istringstream s(line);
      Row r{};
      s >> r.c >> r.mu_i >> r.mu_o >> r.phi_deg >> r.single >> r.single_se >> r.multiple >> r.multiple_se >>
          r.total >> r.total_se;
      EXPECT_FALSE(s.fail()) << line;
      t.rows.push_back(r);
    }
  }
  return t;
}

TEST(HalfspaceReference, TableIsCompleteAndSaysHowToRegenerateIt) {
  const Table t = read_table();
  ASSERT_FALSE(t.rows.empty()) << "tests/data/halfspace_reference.csv missing or empty";
  EXPECT_EQ(t.header, "c,mu_i,mu_o,phi_deg,f_single,f_single_se,f_multiple,f_multiple_se,f_total,f_total_se");
  bool has_command = false;
  for (const std::string& c : t.comments)
    has_command = has_command || c.find("ochre-halfspace --c") != std::string::npos;
  EXPECT_TRUE(has_command);
  for (const Row& r : t.rows) {
    EXPECT_NEAR(r.total, r.single + r.multiple, 1e-7 * r.total + 1e-12);
    EXPECT_GT(r.total_se, 0.0);
    EXPECT_LT(r.total_se, 0.01 * r.total) << "c " << r.c << " mu_i " << r.mu_i << " mu_o " << r.mu_o;
  }
}

TEST(HalfspaceReference, SingleScatteringMatchesClosedForm) {
  const Table t = read_table();
  ASSERT_FALSE(t.rows.empty());
  int outside = 0;
  double worst = 0.0;
  for (const Row& r : t.rows) {
    const Direction wi = direction_from_angles(r.mu_i, 0.0);
    const Direction wo = direction_from_angles(r.mu_o, r.phi_deg * std::numbers::pi / 180.0);
    const double expected = r.c * lambertian_sphere_phase(-dot(wi, wo)) / (r.mu_i + r.mu_o);
    const double z = std::abs(r.single - expected) / r.single_se;
    worst = std::max(worst, z);
    if (z > kSigmas) ++outside;
  }
  EXPECT_EQ(outside, 0) << "largest deviation " << worst << " standard errors";
  RecordProperty("worst_single_sigma", std::to_string(worst));
}

TEST(HalfspaceReference, TotalsAreReciprocal) {
  const Table t = read_table();
  ASSERT_FALSE(t.rows.empty());
  std::map<std::tuple<double, double, double, double>, const Row*> by_key;
  for (const Row& r : t.rows) by_key[{r.c, r.mu_i, r.mu_o, r.phi_deg}] = &r;
  int pairs = 0;
  double worst = 0.0;
  for (const Row& r : t.rows) {
    if (r.mu_i >= r.mu_o) continue;
    const auto it = by_key.find({r.c, r.mu_o, r.mu_i, r.phi_deg});
    ASSERT_NE(it, by_key.end());
    const Row& s = *it->second;
    const double z = std::abs(r.total - s.total) / std::hypot(r.total_se, s.total_se);
    worst = std::max(worst, z);
    EXPECT_LT(z, kSigmas) << "c " << r.c << " mu " << r.mu_i << ", " << r.mu_o << " phi " << r.phi_deg;
    ++pairs;
  }
  EXPECT_GT(pairs, 0);
  RecordProperty("worst_reciprocity_sigma", std::to_string(worst));
}

}  // namespace
}  // namespace ochre::halfspace::test::reference_table_test
