#include <nsm/scene/scene.h>
#include <nsm/scene/scene_entries.h>

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace nsm::scene_entries
{
  std::string format_value(const double value)
  {
    for (int digits = 6;; ++digits)
      {
        std::ostringstream out;
        out.precision(digits);
        out << value;
        if (digits >= 17 || std::strtod(out.str().c_str(), nullptr) == value)
          return out.str();
      }
  }

  void require(const bool         ok,
               const std::string &parameter,
               const std::string &allowed,
               const std::string &value)
  {
    if (!ok)
      throw InputError("parameter '" + parameter + "' = " + value +
                       " is out of range: allowed " + allowed);
  }

  std::string trim(const std::string &s)
  {
    const auto first = s.find_first_not_of(" \t");
    if (first == std::string::npos)
      return "";
    const auto last = s.find_last_not_of(" \t");
    return s.substr(first, last - first + 1);
  }

  double parse_double(const std::string &text, const std::string &parameter)
  {
    // strtod, not stod: a value below the normal range (1e-308, 4.9e-324)
    // is a finite number that underflows gracefully, not an error.
    const std::string trimmed = trim(text);
    char             *end     = nullptr;
    const double      value   = trimmed.empty() ? 0 : std::strtod(trimmed.c_str(), &end);
    if (trimmed.empty() || end != trimmed.c_str() + trimmed.size() || !std::isfinite(value))
      throw InputError("parameter '" + parameter + "': '" + text + "' is not a finite number");
    return value;
  }

  unsigned int get_unsigned(dealii::ParameterHandler &prm, const std::string &name)
  {
    return static_cast<unsigned int>(prm.get_integer(name));
  }
} // namespace nsm::scene_entries
