#include <nsm/output/run_report.h>

#include <iomanip>
#include <ostream>

namespace nsm
{
  void print_report(const RunReport &report, std::ostream &out, const bool verbose)
  {
    if (!report.result.empty())
      {
        out << "Result\n" << std::setprecision(6);
        for (const std::string &line : report.result)
          out << "  " << line << '\n';
      }
    out << "Run summary\n";
    out << "  " << std::left << std::setw(24) << "stage" << std::right
        << std::setw(12) << "wall [s]" << std::setw(12) << "cpu [s]" << '\n';
    for (const StageTiming &s : report.stages)
      out << "  " << std::left << std::setw(24) << s.name << std::right
          << std::fixed << std::setprecision(4) << std::setw(12)
          << s.wall_seconds << std::setw(12) << s.cpu_seconds << '\n';
    out.unsetf(std::ios::fixed);
    out << std::setprecision(6);
    for (const std::string &note : report.notes)
      out << "  " << note << '\n';
    if (verbose)
      for (const std::string &event : report.events)
        out << "    " << event << '\n';
    else if (!report.events.empty())
      out << "  continuation events (folds, leaps, ends): " << report.events.size()
          << ", in continuation.log (--verbose prints them here)\n";
    out << "  files written: " << (report.files.empty() ? "none" : "") << '\n';
    for (const std::string &f : report.files)
      out << "    " << f << '\n';
  }
} // namespace nsm
