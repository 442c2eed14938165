// A study's rows compared over the Backbone omegas they all share with the
// reference (study/study_shared_errors.h).
#include <nsm/study/study_shared_errors.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace
{
  /// study.csv's columns that the shared errors read, and one row's cells.
  nsm::CsvTable table_of(const std::vector<std::vector<std::string>> &rows)
  {
    nsm::CsvTable table{"study.csv", {"energy_error_max", "energy_error_partial", "energy_at_1", "energy_at_2",
                                      "energy_at_3"}, {}};
    for (const auto &row : rows)
      table.rows.emplace_back(row.begin(), row.end());
    return table;
  }

  double cell(const nsm::CsvTable &table, const std::size_t row, const std::string &column)
  {
    const auto c = std::find(table.columns.begin(), table.columns.end(), column) - table.columns.begin();
    return std::stod(nsm::text_cell(table.rows[row], c));
  }
} // namespace

// Omega 1 is missing from one row, Omega 3 from the reference: only Omega 2
// is shared, and each row's error there is |E / E_ref - 1|, whatever its
// errors elsewhere. A row that ended inside the Omegas takes no part and
// does not shrink the shared set.
TEST(SharedErrors, RowsCompareOverTheOmegasTheyAllShare)
{
  nsm::CsvTable table = table_of({{"0.5", "no", "", "1.1", "3"},
                                  {"0.1", "no", "2", "0.9", "3"},
                                  {"0.01", "yes", "", "", ""}});
  nsm::add_shared_errors(table, {1, 2, 3}, {1.0, 1.0, std::nullopt});
  ASSERT_EQ(table.columns.back(), "energy_error_median_shared");
  EXPECT_EQ(cell(table, 0, "shared_omegas"), 1);
  EXPECT_NEAR(cell(table, 0, "energy_error_max_shared"), 0.1, 1e-15);
  EXPECT_NEAR(cell(table, 1, "energy_error_median_shared"), 0.1, 1e-15);
  EXPECT_EQ(nsm::text_cell(table.rows[2], table.columns.size() - 1), "");
}

// No Omega shared: every row's shared errors are empty.
TEST(SharedErrors, NoneSharedLeavesThemEmpty)
{
  nsm::CsvTable table = table_of({{"0.5", "no", "1", "", "3"}, {"0.1", "no", "", "2", ""}});
  nsm::add_shared_errors(table, {1, 2, 3}, {1.0, 1.0, 1.0});
  for (const auto &row : table.rows)
    EXPECT_EQ(nsm::text_cell(row, table.columns.size() - 2), "");
}
