// CSV parsing of spectral tables: header, comments, columns by name and index, and every error
// message naming the file and line.

#include "spectra/csv_table.h"

#include <gtest/gtest.h>

#include <fstream>
#include <stdexcept>
#include <string>

#include "support/test_paths.h"

namespace ochre::csv_table_test {
namespace {

// The message of the exception thrown by parsing `text` as "t.csv" (empty when it parses).
std::string parse_error(const std::string& text) {
  try {
    CsvTable::parse(text, "t.csv");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return {};
}

TEST(CsvTable, ParsesCommentsHeaderAndColumns) {
  const auto t = CsvTable::parse(
      "# a comment\n# another\n\nwavelength_nm, n ,k\n400,1.5,0.1\r\n500,1.4,+2e-1\n", "t.csv");
  EXPECT_EQ(t.source(), "t.csv");
  EXPECT_EQ(t.header(), (std::vector<std::string>{"wavelength_nm", "n", "k"}));
  EXPECT_EQ(t.row_count(), 2u);
  EXPECT_EQ(t.column_count(), 3u);
  EXPECT_EQ(t.wavelengths(), (std::vector<double>{400, 500}));
  EXPECT_EQ(t.column("n"), (std::vector<double>{1.5, 1.4}));
  EXPECT_EQ(t.column(2), (std::vector<double>{0.1, 0.2}));
  EXPECT_EQ(t.column_index("k"), 2u);
}

TEST(CsvTable, HeaderIsOptional) {
  const auto t = CsvTable::parse("# no header\n400,0.5\n410,0.6\n420,0.7\n", "t.csv");
  EXPECT_TRUE(t.header().empty());
  EXPECT_EQ(t.row_count(), 3u);
  EXPECT_EQ(t.column(1), (std::vector<double>{0.5, 0.6, 0.7}));
  EXPECT_THROW(t.column("S"), std::runtime_error);
}

TEST(CsvTable, ErrorsNameFileAndLine) {
  EXPECT_EQ(parse_error("l,v\n400,1\n410,abc\n"), "t.csv:3: non-numeric value 'abc' in column 2");
  EXPECT_EQ(parse_error("l,v\n400,1\n410,\n"), "t.csv:3: non-numeric value '' in column 2");
  EXPECT_EQ(parse_error("l,v\n400,nan\n410,1\n"), "t.csv:2: NaN value in column 2");
  EXPECT_EQ(parse_error("l,v\n400,inf\n410,1\n"), "t.csv:2: infinite value in column 2");
  EXPECT_EQ(parse_error("l,v\n400,1\n# c\n410,1,2\n"), "t.csv:4: expected 2 columns, found 3");
  EXPECT_EQ(parse_error("l,v\n400,1\n400,2\n"),
            "t.csv:3: wavelengths must be strictly increasing (400 after 400 on line 2)");
  EXPECT_EQ(parse_error("l,v\n400,1\n390,2\n"),
            "t.csv:3: wavelengths must be strictly increasing (390 after 400 on line 2)");
  EXPECT_EQ(parse_error("# only\nl,v\n400,1\n"), "t.csv: fewer than 2 data rows (found 1)");
  EXPECT_EQ(parse_error(""), "t.csv: fewer than 2 data rows (found 0)");
  EXPECT_EQ(parse_error("lambda\n400\n"),
            "t.csv:1: expected at least 2 columns (wavelength and values), found 1");
}

TEST(CsvTable, UnknownColumnListsTheColumns) {
  const auto t = CsvTable::parse("l,n,k\n400,1,2\n500,1,2\n", "t.csv");
  try {
    t.column("eta");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "t.csv: no column 'eta' (columns: l, n, k)");
  }
  EXPECT_THROW(t.column(3), std::runtime_error);
}

TEST(CsvTable, LoadsFilesAndReportsMissingOnes) {
  const auto dir = test::scratch_dir();
  const auto path = dir / "refl.csv";
  std::ofstream(path) << "# user data\nnm,R\n400,0.2\n700,0.8\n";
  const auto t = CsvTable::load(path);
  EXPECT_EQ(t.source(), path.string());
  EXPECT_EQ(t.column("R"), (std::vector<double>{0.2, 0.8}));

  std::ofstream(dir / "bad.csv") << "nm,R\n400,0.2\n700,x\n";
  try {
    CsvTable::load(dir / "bad.csv");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "bad.csv").string() + ":3: non-numeric value 'x' in column 2");
  }
  try {
    CsvTable::load(dir / "missing.csv");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / "missing.csv").string() + ": cannot open file (missing or unreadable)");
  }
}

}  // namespace
}  // namespace ochre::csv_table_test
