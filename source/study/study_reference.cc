#include <nsm/base/csv.h>
#include <nsm/study/study_reference.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace nsm
{
  namespace
  {
    const char *const quantities[] = {"energy", "max_contact_force", "contact_fraction"};

    std::string level_name(const StudyScene &level)
    {
      return "FE_Q(" + std::to_string(level.scene.discretisation.degree) + ") x " +
             std::to_string(level.scene.discretisation.cells) + " cells at M = " +
             std::to_string(level.scene.harmonic_balance.harmonics);
    }

    std::string column(const std::string &quantity, const StudyScene &level)
    {
      return quantity + "_cells_" + std::to_string(level.scene.discretisation.cells);
    }

    double value_of(const MainBranchPoint &p, const std::size_t q)
    {
      return q == 0 ? p.energy : q == 1 ? p.max_contact_force : p.contact_fraction;
    }

    /// Energy and force change relatively, the contact fraction absolutely.
    double change(const MainBranchPoint &fine, const MainBranchPoint &coarse, const std::size_t q)
    {
      const double difference = std::abs(value_of(fine, q) - value_of(coarse, q));
      return q < 2 ? difference / std::abs(value_of(fine, q)) : difference;
    }

    CsvTable reference_table(const std::vector<StudyScene> &levels)
    {
      const std::vector<double> &omegas = levels.front().study.backbone_omega_values;
      std::vector<std::vector<std::optional<MainBranchPoint>>> points;
      for (const StudyScene &level : levels)
        points.push_back(main_branch_at(level));
      CsvTable table{"reference.csv", {"Omega"}, {}};
      for (const StudyScene &level : levels)
        for (const char *q : quantities)
          table.columns.push_back(column(q, level));
      for (const char *q : quantities)
        table.columns.push_back(std::string(q) + "_change");
      for (std::size_t i = 0; i < omegas.size(); ++i)
        {
          std::vector<CsvCell> row = {omegas[i]};
          for (const auto &level : points)
            for (std::size_t q = 0; q < 3; ++q)
              row.push_back(level[i] ? CsvCell(value_of(*level[i], q)) : CsvCell(std::string()));
          const auto &fine = points.back()[i], &coarse = points[points.size() - 2][i];
          for (std::size_t q = 0; q < 3; ++q)
            row.push_back(fine && coarse ? CsvCell(change(*fine, *coarse, q)) : CsvCell(std::string()));
          table.rows.push_back(std::move(row));
        }
      return table;
    }

    /// The cells of `name`'s column, as numbers (empty: none).
    std::vector<std::optional<double>> column_values(const CsvTable &table, const std::string &name)
    {
      const auto c = std::find(table.columns.begin(), table.columns.end(), name);
      if (c == table.columns.end())
        throw InputError("reference.csv has no column " + name +
                         "; allowed: a reference.csv written by this study (delete it to recompute)");
      std::vector<std::optional<double>> values;
      for (const auto &row : table.rows)
        {
          const std::string &cell = text_cell(row, c - table.columns.begin());
          values.push_back(cell.empty() ? std::nullopt : std::optional<double>(std::stod(cell)));
        }
      return values;
    }
  } // namespace

  std::string keep_fine_reference(const std::vector<StudyScene> &levels, const std::string &directory)
  {
    const std::string path = directory + "/reference.csv";
    if (std::filesystem::exists(path))
      return "read from " + path;
    const auto start = std::chrono::steady_clock::now();
    write_csv(directory, reference_table(levels));
    std::ostringstream origin;
    origin.precision(3);
    origin << "computed in " << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
           << " s";
    return origin.str();
  }

  std::vector<std::string> fine_reference_notes(const CsvTable &table, const std::vector<StudyScene> &levels,
                                                const std::string &origin)
  {
    std::ostringstream note;
    note.precision(3);
    const std::vector<std::optional<double>> found = column_values(table, column("energy", levels.back()));
    note << "fine reference: " << level_name(levels.back()) << ", " << origin << "; on the main branch at "
         << std::count_if(found.begin(), found.end(), [](auto v) { return v.has_value(); }) << " of "
         << found.size() << " Omega";
    std::ostringstream changes;
    changes.precision(3);
    changes << "  largest change from " << level_name(levels[levels.size() - 2]) << ":";
    for (const char *q : quantities)
      {
        double largest = 0;
        for (const auto &v : column_values(table, std::string(q) + "_change"))
          largest = std::max(largest, v.value_or(0.0));
        changes << " " << q << " " << largest;
      }
    std::vector<std::string> notes{note.str(), changes.str()};
    // Its M is the base scene's: a sweep of Harmonics at or above it is
    // compared with a reference no better converged in M than itself.
    for (const StudyParameters::Sweep &sweep : levels.back().study.sweeps)
      if (sweep.name == "Harmonics" && !sweep.values.empty())
        {
          const unsigned int m       = levels.back().scene.harmonic_balance.harmonics;
          std::string        at_or_above;
          for (const std::string &value : sweep.values)
            if (std::stoul(value) >= m)
              at_or_above += (at_or_above.empty() ? "" : ", ") + value;
          if (!at_or_above.empty())
            notes.push_back("  warning: the reference has M = " + std::to_string(m) +
                            " (Harmonic balance/Harmonics), and the rows at M = " + at_or_above +
                            " are compared with it: their energy errors are the mesh's alone (at M = " +
                            std::to_string(m) + ") or against a less converged M; set Harmonic balance/Harmonics "
                            "above every swept value for a reference converged in M");
        }
    return notes;
  }

  FineReference read_fine_reference(const CsvTable &table, const std::vector<StudyScene> &levels)
  {
    FineReference reference{level_name(levels.back()) + " (reference.csv)", {}};
    const auto    energy = column_values(table, column("energy", levels.back()));
    const auto    force  = column_values(table, column("max_contact_force", levels.back()));
    const auto    share  = column_values(table, column("contact_fraction", levels.back()));
    if (energy.size() != levels.back().study.backbone_omega_values.size())
      throw InputError("reference.csv has " + std::to_string(energy.size()) + " rows; allowed: " +
                       std::to_string(levels.back().study.backbone_omega_values.size()) +
                       ", one per Study/Backbone omegas (delete it to recompute)");
    for (std::size_t i = 0; i < energy.size(); ++i)
      reference.points.push_back(energy[i] && force[i] && share[i] ?
                                   std::optional<MainBranchPoint>({*energy[i], *force[i], *share[i]}) :
                                   std::nullopt);
    return reference;
  }
} // namespace nsm
