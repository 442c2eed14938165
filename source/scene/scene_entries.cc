#include <nsm/scene/scene.h>
#include <nsm/scene/scene_entries.h>

#include <cmath>
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
        if (digits >= 17 || std::stod(out.str()) == value)
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
    std::size_t used = 0;
    double      value;
    try
      {
        value = std::stod(text, &used);
      }
    catch (const std::exception &)
      {
        used = 0;
      }
    if (used == 0 || trim(text.substr(used)) != "" || !std::isfinite(value))
      throw InputError("parameter '" + parameter + "': '" + text +
                       "' is not a finite number");
    return value;
  }

  unsigned int get_unsigned(dealii::ParameterHandler &prm, const std::string &name)
  {
    return static_cast<unsigned int>(prm.get_integer(name));
  }
} // namespace nsm::scene_entries
