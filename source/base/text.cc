#include <nsm/base/text.h>

#include <cstdio>
#include <sstream>

namespace nsm
{
  namespace
  {
    bool is_control(const char c)
    {
      const auto u = static_cast<unsigned char>(c);
      return u < 0x20 || u == 0x7f;
    }
  } // namespace

  std::string printable(const std::string &text)
  {
    std::string out;
    for (const char c : text)
      if (is_control(c))
        {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\x%02x", static_cast<unsigned char>(c));
          out += escaped;
        }
      else
        out += c;
    return out;
  }

  bool has_control_character(const std::string &text)
  {
    for (const char c : text)
      if (is_control(c))
        return true;
    return false;
  }

  std::string significant(const double value, const int digits)
  {
    std::ostringstream s;
    s.precision(digits);
    s << value;
    return s.str();
  }
} // namespace nsm
