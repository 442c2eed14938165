#include <nsm/scene/scene.h>
#include <nsm/scene/scene_entries.h>
#include <nsm/base/text.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <cerrno>
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

  std::vector<std::string> list_items(const std::string &text, const std::string &parameter)
  {
    std::vector<std::string> items;
    if (trim(text).empty())
      return items;
    // getline drops a trailing empty field: "1," reads as one item.
    const bool trailing = trim(text).back() == ',';
    std::stringstream in(text);
    for (std::string item; std::getline(in, item, ',');)
      items.push_back(trim(item));
    if (trailing || std::any_of(items.begin(), items.end(), [](const std::string &i) { return i.empty(); }))
      throw InputError("parameter '" + parameter + "' = '" + printable(text) +
                       "' has an empty item; allowed: comma-separated values (or nothing: an empty list)");
    return items;
  }

  bool outside_normal_range(const std::string &text)
  {
    errno              = 0;
    const double value = std::strtod(trim(text).c_str(), nullptr);
    return errno == ERANGE || (value != 0 && std::abs(value) < std::numeric_limits<double>::min());
  }

  double parse_double(const std::string &text, const std::string &parameter)
  {
    const std::string trimmed = trim(text);
    char             *end     = nullptr;
    const double      value   = trimmed.empty() ? 0 : std::strtod(trimmed.c_str(), &end);
    if (trimmed.empty() || end != trimmed.c_str() + trimmed.size() || !std::isfinite(value))
      throw InputError("parameter '" + parameter + "': '" + printable(text) + "' is not a finite number");
    if (outside_normal_range(trimmed))
      throw InputError("parameter '" + parameter + "': '" + printable(text) +
                       "' is subnormal (of magnitude below 2.2e-308): allowed, 0 or a normal number");
    return value;
  }

  unsigned int get_unsigned(dealii::ParameterHandler &prm, const std::string &name)
  {
    return static_cast<unsigned int>(prm.get_integer(name));
  }
} // namespace nsm::scene_entries
