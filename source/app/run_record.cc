#include <nsm/app/run_record.h>
#include <nsm/base/csv.h>
#include <nsm/base/text.h>

#include <deal.II/base/config.h>

#include <Trilinos_version.h>
#include <nsm_version.h>

#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

#include <sys/utsname.h>

namespace nsm
{
  namespace
  {
    /// `argument` as one shell word: as it is if it holds only safe
    /// characters, else in single quotes.
    std::string shell_word(const std::string &argument)
    {
      const std::string safe = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789@%_+=:,./-";
      if (!argument.empty() && argument.find_first_not_of(safe) == std::string::npos)
        return printable(argument);
      std::string word = "'";
      for (const char c : argument)
        word += c == '\'' ? std::string("'\\''") : std::string(1, c);
      return printable(word + "'");
    }

    std::string utc_now()
    {
      const std::time_t now = std::time(nullptr);
      std::tm           utc{};
      gmtime_r(&now, &utc);
      char text[32];
      std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
      return text;
    }

    /// The processor's model name (/proc/cpuinfo), or "" if unknown.
    std::string processor()
    {
      std::ifstream in("/proc/cpuinfo");
      for (std::string line; std::getline(in, line);)
        if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos)
          return line.substr(line.find(':') + 2);
      return "";
    }

    std::string machine()
    {
      utsname name{};
      std::ostringstream out;
      if (uname(&name) == 0)
        out << name.nodename << ", " << name.sysname << ' ' << name.release << ' ' << name.machine;
      out << ", " << std::thread::hardware_concurrency() << " cores";
      if (const std::string cpu = processor(); !cpu.empty())
        out << ", " << cpu;
      return printable(out.str());
    }
  } // namespace

  std::string quoted_command_line(const std::vector<std::string> &arguments)
  {
    std::string line;
    for (const std::string &argument : arguments)
      line += (line.empty() ? "" : " ") + shell_word(argument);
    return line;
  }

  std::string record_header(const std::string &command_line)
  {
    std::ostringstream out;
    out << "command: " << command_line << "\nversion: " << NSM_VERSION << "\ndeal.II: " << DEAL_II_PACKAGE_VERSION
        << "\nTrilinos: " << TRILINOS_VERSION_STRING << "\ndate: " << utc_now() << "\nmachine: " << machine()
        << '\n';
    return out.str();
  }

  void write_summary(const std::string &path, const std::string &command_line, const RunReport &report)
  {
    write_atomically(path, [&](std::ostream &out) {
      out << record_header(command_line);
      print_report(report, out, true);
    });
  }
} // namespace nsm
