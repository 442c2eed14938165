#include <nsm/scene/parameter_listing.h>
#include <nsm/scene/scene_file.h>

#include <deal.II/base/parameter_handler.h>

#include <ostream>
#include <string>

namespace nsm
{
  namespace
  {
    /// Text inside a table cell: a '|' would end the cell.
    std::string cell(const std::string &text)
    {
      std::string out;
      for (const char c : text)
        out += c == '|' ? std::string("\\|") : std::string(1, c);
      return out;
    }

    std::string allowed(const std::string &pattern)
    {
      return pattern == "[Anything]" ? "text" : allowed_values(pattern);
    }
  } // namespace

  void print_parameters_markdown(const dealii::ParameterHandler &prm, std::ostream &out)
  {
    std::string section;
    for (const DeclaredEntry &e : declared_entries(prm))
      {
        if (e.sections.front() != section)
          {
            section = e.sections.front();
            out << "\n## " << section << "\n| parameter | default | allowed | meaning |\n|---|---|---|---|\n";
          }
        std::string name;
        for (std::size_t i = 1; i < e.sections.size(); ++i)
          name += e.sections[i] + "/";
        out << "| `" << cell(name + e.name) << "` | `" << cell(e.default_value) << "` | " << cell(allowed(e.pattern))
            << " | " << cell(e.documentation) << " |\n";
      }
  }
} // namespace nsm
