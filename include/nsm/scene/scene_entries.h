// What the scene's subsections share to declare and parse their entries:
// values as text, range checks with one-line messages, and named options.
#pragma once

#include <nsm/scene/parameter_limits.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace nsm::scene_entries
{
  /// The names every subsection's declare and parse use.
  using dealii::ParameterHandler;
  namespace Patterns = dealii::Patterns;

  /// The shortest text that reads back as the same double.
  std::string format_value(double value);

  inline std::string text(const double value) { return format_value(value); }
  inline std::string text(const unsigned int value) { return std::to_string(value); }
  inline std::string text(const bool value) { return value ? "true" : "false"; }

  /// The pattern of a dimensional input (L, E, rho, g0, alpha, k):
  /// [1 / magnitude_limit, magnitude_limit].
  inline dealii::Patterns::Double dimensional()
  {
    return dealii::Patterns::Double(1 / magnitude_limit, magnitude_limit);
  }

  /// Throws InputError "parameter 'P' = value is out of range: allowed A"
  /// unless `ok`.
  void require(bool ok, const std::string &parameter, const std::string &allowed, const std::string &value);

  /// `s` without its leading and trailing blanks and tabs.
  std::string trim(const std::string &s);

  /// The comma-separated items of the list entry `parameter`, trimmed; an
  /// empty text is the empty list, and an empty item in a list ("1,,2",
  /// ",") is refused (InputError naming the parameter).
  std::vector<std::string> list_items(const std::string &text, const std::string &parameter);

  /// A finite number, all of `text`; else an InputError naming `parameter`.
  /// A subnormal one is refused too (outside_normal_range).
  double parse_double(const std::string &text, const std::string &parameter);

  /// Whether strtod reads `text` only outside the normal range of doubles:
  /// by underflow (1e-400), as a subnormal (1e-310, 4.9e-324) or by
  /// overflow. A scene's number never is, in an entry or in a list.
  bool outside_normal_range(const std::string &text);

  /// An Integer entry whose pattern allows no negative value.
  unsigned int get_unsigned(dealii::ParameterHandler &prm, const std::string &name);

  /// The names of an enumeration's values in a Selection pattern.
  template <typename Enum>
  using Options = std::vector<std::pair<std::string, Enum>>;

  template <typename Enum>
  dealii::Patterns::Selection selection(const Options<Enum> &options)
  {
    std::string names;
    for (const auto &[name, value] : options)
      names += (names.empty() ? "" : "|") + name;
    return dealii::Patterns::Selection(names);
  }

  template <typename Enum>
  std::string name_of(const Enum value, const Options<Enum> &options)
  {
    for (const auto &[name, v] : options)
      if (v == value)
        return name;
    return options.front().first;
  }

  /// A Selection value (already checked against its pattern).
  template <typename Enum>
  Enum selected(const std::string &name, const Options<Enum> &options)
  {
    for (const auto &[n, value] : options)
      if (n == name)
        return value;
    return options.front().second;
  }
} // namespace nsm::scene_entries
