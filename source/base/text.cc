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

    /// The length of the valid UTF-8 sequence that starts at text[i], or 0
    /// if none does (a stray continuation byte, an overlong form, a
    /// surrogate, a code point beyond U+10FFFF, a truncated sequence).
    std::size_t utf8_length(const std::string &text, const std::size_t i)
    {
      const auto byte = [&](const std::size_t k) { return static_cast<unsigned char>(text[k]); };
      const unsigned char lead = byte(i);
      if (lead < 0x80)
        return 1;
      std::size_t   length;
      unsigned char low = 0x80, high = 0xbf; // the second byte's range
      if (lead >= 0xc2 && lead <= 0xdf)
        length = 2;
      else if (lead >= 0xe0 && lead <= 0xef)
        {
          length = 3;
          low    = lead == 0xe0 ? 0xa0 : 0x80;
          high   = lead == 0xed ? 0x9f : 0xbf;
        }
      else if (lead >= 0xf0 && lead <= 0xf4)
        {
          length = 4;
          low    = lead == 0xf0 ? 0x90 : 0x80;
          high   = lead == 0xf4 ? 0x8f : 0xbf;
        }
      else
        return 0;
      if (i + length > text.size() || byte(i + 1) < low || byte(i + 1) > high)
        return 0;
      for (std::size_t k = 2; k < length; ++k)
        if (byte(i + k) < 0x80 || byte(i + k) > 0xbf)
          return 0;
      return length;
    }

    /// A C1 control character (U+0080 to U+009F, such as CSI and NEL) at
    /// text[i], in UTF-8: 0xC2 then 0x80 to 0x9F.
    bool is_c1_control(const std::string &text, const std::size_t i)
    {
      return i + 1 < text.size() && static_cast<unsigned char>(text[i]) == 0xc2 &&
             static_cast<unsigned char>(text[i + 1]) >= 0x80 && static_cast<unsigned char>(text[i + 1]) <= 0x9f;
    }

    std::string escaped(const char c)
    {
      char text[8];
      std::snprintf(text, sizeof text, "\\x%02x", static_cast<unsigned char>(c));
      return text;
    }
  } // namespace

  std::string printable(const std::string &text)
  {
    std::string out;
    for (std::size_t i = 0; i < text.size();)
      {
        const std::size_t length = utf8_length(text, i);
        if (is_c1_control(text, i))
          {
            out += escaped(text[i]) + escaped(text[i + 1]);
            i += 2;
          }
        else if (length == 0 || (length == 1 && is_control(text[i])))
          out += escaped(text[i++]);
        else
          {
            out += text.substr(i, length);
            i += length;
          }
      }
    return out;
  }

  bool has_control_character(const std::string &text)
  {
    for (std::size_t i = 0; i < text.size(); ++i)
      if (is_control(text[i]) || is_c1_control(text, i))
        return true;
    return false;
  }

  std::size_t first_invalid_utf8(const std::string &text)
  {
    for (std::size_t i = 0; i < text.size();)
      {
        const std::size_t length = utf8_length(text, i);
        if (length == 0)
          return i;
        i += length;
      }
    return std::string::npos;
  }

  bool is_valid_utf8(const std::string &text) { return first_invalid_utf8(text) == std::string::npos; }

  std::string significant(const double value, const int digits)
  {
    std::ostringstream s;
    s.precision(digits);
    s << value;
    return s.str();
  }

  std::string counted(const std::size_t n, const std::string &noun)
  {
    return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
  }
} // namespace nsm
