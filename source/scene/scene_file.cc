#include <nsm/scene/scene.h>
#include <nsm/scene/scene_file.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace nsm
{
  namespace
  {
    namespace fs = std::filesystem;

    /// ParameterHandler's tree names replace each character that is not a
    /// letter or digit by '_' and two hexadecimal digits.
    std::string demangle(const std::string &name)
    {
      std::string out;
      for (std::size_t i = 0; i < name.size(); ++i)
        if (name[i] == '_' && i + 2 < name.size() && std::isxdigit(name[i + 1]) &&
            std::isxdigit(name[i + 2]))
          {
            out += static_cast<char>(std::stoi(name.substr(i + 1, 2), nullptr, 16));
            i += 2;
          }
        else
          out += name[i];
      return out;
    }

    void collect(const boost::property_tree::ptree &tree,
                 std::vector<std::string>          &sections,
                 std::vector<DeclaredEntry>        &entries)
    {
      for (const auto &[key, child] : tree)
        if (child.count("value") != 0)
          entries.push_back({sections,
                             demangle(key),
                             child.get<std::string>("default_value"),
                             child.get<std::string>("pattern_description"),
                             child.get<std::string>("documentation", "")});
        else
          {
            sections.push_back(demangle(key));
            collect(child, sections, entries);
            sections.pop_back();
          }
    }

    template <typename Action>
    void in_sections(dealii::ParameterHandler &prm, const DeclaredEntry &entry, const Action &action)
    {
      for (const std::string &s : entry.sections)
        prm.enter_subsection(s);
      action();
      for (std::size_t i = 0; i < entry.sections.size(); ++i)
        prm.leave_subsection();
    }

    /// The file named by an `include` line of a PRM file (deal.II opens it
    /// relative to the working directory), or "" for any other line.
    std::string included_file(std::string line)
    {
      line = line.substr(0, line.find('#'));
      const std::size_t first = line.find_first_not_of(" \t");
      if (first == std::string::npos)
        return "";
      line = line.substr(first);
      if (line.rfind("include ", 0) != 0 && line.rfind("INCLUDE ", 0) != 0)
        return "";
      line = line.substr(8);
      line.erase(0, line.find_first_not_of(" \t"));
      line.erase(line.find_last_not_of(" \t\r") + 1);
      return line;
    }

    /// A readable regular file, whose includes (PRM only) are readable
    /// regular files too and never include a file that includes them.
    void check_file(const std::string &path, std::vector<fs::path> &chain)
    {
      std::error_code error;
      const fs::file_status status = fs::status(path, error);
      if (!fs::exists(status))
        throw InputError("scene '" + path + "' does not exist");
      if (!fs::is_regular_file(status))
        throw InputError("scene '" + path + "' is not a regular file");
      std::ifstream file(path);
      if (!file)
        throw InputError("scene '" + path + "' cannot be read");
      const fs::path canonical = fs::canonical(path, error);
      for (const fs::path &outer : chain)
        if (outer == canonical)
          throw InputError("scene '" + chain.front().string() + "' includes '" + path +
                           "' inside itself (an include cycle)");
      if (fs::path(path).extension() != ".prm")
        return;
      chain.push_back(canonical);
      std::string line;
      while (std::getline(file, line))
        {
          const std::string included = included_file(line);
          if (!included.empty())
            check_file(included, chain);
        }
      chain.pop_back();
    }

    std::string number_in_words(const std::string &text)
    {
      if (text == "MAX_DOUBLE")
        return "no upper bound";
      if (text == "-MAX_DOUBLE")
        return "no lower bound";
      return text;
    }
  } // namespace

  std::vector<DeclaredEntry> declared_entries(const dealii::ParameterHandler &prm)
  {
    std::stringstream json;
    prm.print_parameters(json, dealii::ParameterHandler::JSON);
    boost::property_tree::ptree tree;
    boost::property_tree::read_json(json, tree);
    std::vector<std::string> sections;
    std::vector<DeclaredEntry>       entries;
    collect(tree, sections, entries);
    return entries;
  }

  std::string allowed_values(const std::string &description)
  {
    std::smatch match;
    if (std::regex_match(description,
                         match,
                         std::regex(R"(\[(Double|Integer range) (\S+)\.\.\.(\S+) \(inclusive\)\])")))
      return std::string(match[1] == "Double" ? "a number" : "an integer") + " in [" +
             number_in_words(match[2]) + ", " + number_in_words(match[3]) + "]";
    if (std::regex_match(description, match, std::regex(R"(\[Selection (.*) \])")))
      return "one of " + std::regex_replace(std::string(match[1]), std::regex(R"(\|)"), ", ");
    if (description == "[Bool]")
      return "true or false";
    return description;
  }

  void read_scene_file(const std::string &path, dealii::ParameterHandler &prm)
  {
    std::vector<fs::path> chain;
    check_file(path, chain);

    // Every entry as text first: deal.II's own pattern errors name neither
    // the subsection nor the range in words.
    const std::vector<DeclaredEntry> entries = declared_entries(prm);
    dealii::ParameterHandler text;
    for (const DeclaredEntry &entry : entries)
      in_sections(text, entry, [&] {
        text.declare_entry(entry.name, entry.default_value, dealii::Patterns::Anything());
      });
    try
      {
        text.parse_input(path);
      }
    catch (const dealii::ExceptionBase &e)
      {
        throw InputError("scene '" + path + "': " + one_line_message(e));
      }
    catch (const std::exception &e)
      {
        throw InputError("scene '" + path + "' cannot be parsed: " + e.what());
      }

    for (const DeclaredEntry &entry : entries)
      {
        std::string value;
        in_sections(text, entry, [&] { value = text.get(entry.name); });
        if (!dealii::Patterns::pattern_factory(entry.pattern)->match(value))
          throw InputError("scene '" + path + "': parameter '" + entry.path() + "' = " + value +
                           " is out of range: allowed " + allowed_values(entry.pattern));
        in_sections(prm, entry, [&] { prm.set(entry.name, value); });
      }
  }

  void require_allowed(const dealii::ParameterHandler &prm, const std::vector<AllowedCheck> &checks)
  {
    if (checks.empty())
      return;
    const std::vector<DeclaredEntry> entries = declared_entries(prm);
    for (const AllowedCheck &check : checks)
      {
        const auto entry = std::find_if(entries.begin(), entries.end(),
                                        [&](const DeclaredEntry &e) { return e.path() == check.entry_path; });
        if (entry == entries.end())
          throw InputError("parameter '" + check.parameter + "': no scene parameter " + check.entry_path);
        if (!dealii::Patterns::pattern_factory(entry->pattern)->match(check.value))
          throw InputError("parameter '" + check.parameter + "': value '" + check.value + "' of " +
                           check.entry_path + " is out of range: allowed " + allowed_values(entry->pattern));
      }
  }
} // namespace nsm
