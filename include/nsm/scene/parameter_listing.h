// The declared parameters as the Markdown tables of doc/parameters.md, so
// that the documentation's defaults and ranges are the declarations' own.
#pragma once

#include <iosfwd>

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  /// One table per top-level subsection: each entry's name (relative to the
  /// subsection), default, allowed values in words and documentation.
  void print_parameters_markdown(const dealii::ParameterHandler &prm, std::ostream &out);
} // namespace nsm
