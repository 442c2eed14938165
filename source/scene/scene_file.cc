#include <nsm/base/text.h>
#include <nsm/scene/scene.h>
#include <nsm/scene/scene_entries.h>
#include <nsm/scene/scene_file.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/patterns.h>

#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <optional>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
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
                             child.get<std::string>("documentation", ""),
                             child.get<std::string>("value")});
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

    /// Declares every entry in `text` with its default and any value as
    /// text: a scene is parsed so first, and its values checked after.
    void declare_as_text(dealii::ParameterHandler &text, const std::vector<DeclaredEntry> &entries)
    {
      for (const DeclaredEntry &entry : entries)
        in_sections(text, entry, [&] {
          text.declare_entry(entry.name, entry.default_value, dealii::Patterns::Anything());
        });
    }

    /// deal.II's reading of a PRM line: surrounding white space (isspace)
    /// removed.
    std::string trimmed(const std::string &line)
    {
      const auto space = [](const char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
      std::size_t begin = 0, end = line.size();
      while (begin < end && space(line[begin]))
        ++begin;
      while (end > begin && space(line[end - 1]))
        --end;
      return line.substr(begin, end - begin);
    }

    /// The logical lines of a PRM text: each trimmed, and one ending in a
    /// backslash joined to the next without it, as deal.II joins them.
    std::vector<std::string> logical_lines(std::istream &in, std::vector<std::size_t> *first_lines = nullptr)
    {
      std::vector<std::string> lines;
      bool                     continued = false;
      std::size_t              number    = 0;
      for (std::string line; std::getline(in, line);)
        {
          ++number;
          line              = trimmed(line);
          const bool joined = !line.empty() && line.back() == '\\'; // this physical line goes on
          if (joined)
            line.pop_back();
          if (continued)
            lines.back() += line;
          else
            {
              lines.push_back(line);
              if (first_lines)
                first_lines->push_back(number);
            }
          continued = joined;
        }
      return lines;
    }

    /// Where a line of the flattened text came from: its file and the
    /// physical line its logical line starts at.
    struct LineOrigin
    {
      std::string file;
      std::size_t line;
    };

    /// The file an include line names, or nullopt for any other line. Every
    /// line that starts with "include" in any case is one, so that deal.II,
    /// which reads the flattened text, never meets an include of its own.
    std::optional<std::string> included_file(const std::string &line)
    {
      if (line.size() < 7 || !std::equal(line.begin(), line.begin() + 7, "include",
                                         [](const char a, const char b) { return std::tolower(a) == b; }))
        return std::nullopt;
      return trimmed(line.substr(7, line.find('#') == std::string::npos ? std::string::npos : line.find('#') - 7));
    }

    /// A name as a message shows it: control characters escaped, so that a
    /// message stays one line.
    std::string shown(const std::string &name) { return printable(name); }

    /// A readable regular file, its canonical path.
    fs::path readable_file(const std::string &path)
    {
      std::error_code       error;
      const fs::file_status status = fs::status(path, error);
      if (!fs::exists(status))
        throw InputError("scene '" + shown(path) + "' does not exist");
      if (fs::is_directory(status))
        throw InputError("scene '" + shown(path) + "' is a folder, not a scene file: nsm-bar " + shown(path) +
                         " --resume goes on with a stopped run from its record (parameters.prm), and nsm-bar " +
                         shown(path) + "/parameters.prm --output NEW runs that record again");
      if (!fs::is_regular_file(status))
        throw InputError("scene '" + shown(path) + "' is not a regular file");
      if (!std::ifstream(path))
        throw InputError("scene '" + shown(path) + "' cannot be read");
      return fs::canonical(path, error);
    }

    /// The PRM text of `path` with its includes replaced by their own
    /// flattened texts (names relative to the working directory, as deal.II
    /// reads them). A file included inside itself, by any path to it, is a
    /// cycle; more than max_include_depth nested includes are refused.
    void flatten(const std::string &path, std::vector<fs::path> &chain, std::ostream &out, std::size_t &files,
                 std::vector<LineOrigin> &origins)
    {
      if (++files > max_included_files)
        throw InputError("scene '" + shown(chain.empty() ? path : chain.front().string()) + "' includes more than " +
                         std::to_string(max_included_files) + " files in all");
      const fs::path canonical = readable_file(path);
      if (std::find(chain.begin(), chain.end(), canonical) != chain.end())
        throw InputError("scene '" + shown(chain.front().string()) + "' includes '" + shown(path) +
                         "' inside itself (an include cycle)");
      if (chain.size() > max_include_depth)
        throw InputError("scene '" + shown(chain.front().string()) + "': includes nested deeper than " +
                         std::to_string(max_include_depth) + " at '" + shown(path) + "'");
      chain.push_back(canonical);
      std::ifstream            file(path);
      std::vector<std::size_t> numbers;
      const std::vector<std::string> lines = logical_lines(file, &numbers);
      for (std::size_t i = 0; i < lines.size(); ++i)
        if (const auto included = included_file(lines[i]))
          {
            if (included->empty())
              throw InputError("scene '" + shown(path) + "': an include line names no file");
            flatten(*included, chain, out, files, origins);
          }
        else
          {
            out << lines[i] << '\n';
            origins.push_back({path, numbers[i]});
          }
      chain.pop_back();
    }

    /// Walks a JSON text up to `end`: `mark(i)` at each character outside
    /// strings but white space, `string(start, i)` at the closing quote (at
    /// i) of each string that began at `start`. True if `end` lies inside a
    /// string.
    template <typename Mark, typename String>
    bool walk_json(const std::string &text, const std::size_t end, Mark mark, String string)
    {
      bool        quoted = false;
      std::size_t start  = 0;
      for (std::size_t i = 0; i < end; ++i)
        if (quoted)
          {
            if (text[i] == '\\')
              ++i; // an escaped character, '"' too
            else if (text[i] == '"')
              quoted = false, string(start, i);
          }
        else if (text[i] == '"')
          quoted = true, start = i + 1;
        else if (!std::isspace(static_cast<unsigned char>(text[i])))
          mark(i);
      return quoted;
    }

    /// The deepest nesting of a JSON text: brackets and braces outside
    /// strings.
    std::size_t json_depth(const std::string &text)
    {
      std::size_t depth = 0, deepest = 0;
      walk_json(
        text, text.size(),
        [&](const std::size_t i) {
          if (text[i] == '{' || text[i] == '[')
            deepest = std::max(deepest, ++depth);
          else if ((text[i] == '}' || text[i] == ']') && depth > 0)
            --depth;
        },
        [](std::size_t, std::size_t) {});
      return deepest;
    }

    /// The deepest nesting of an XML text: elements opened ("<name") and
    /// not yet closed ("</name>" or "/>").
    std::size_t xml_depth(const std::string &text)
    {
      std::size_t depth = 0, deepest = 0;
      bool        in_tag = false, closing = false;
      char        previous = 0;
      for (const char c : text)
        {
          if (previous == '<' && !in_tag)
            {
              // "<name": an element opens (a declaration "<?", "<!" does not);
              // "</name>" closes one.
              in_tag  = true;
              closing = c == '/';
              if (!closing && c != '?' && c != '!')
                deepest = std::max(deepest, ++depth);
            }
          else if (c == '>' && in_tag)
            {
              // "</name>" and "<name/>" close an element.
              if ((closing || previous == '/') && depth > 0)
                --depth;
              in_tag = false;
            }
          previous = c;
        }
      return deepest;
    }

    /// JSON and XML scenes are parsed recursively (boost's property tree):
    /// nesting deeper than max_nesting_depth is refused before.
    void check_nesting(const std::string &path, const std::string &text, const bool json)
    {
      const std::size_t depth = json ? json_depth(text) : xml_depth(text);
      if (depth > max_nesting_depth)
        throw InputError("scene '" + shown(path) + "' is nested " + std::to_string(depth) +
                         " levels deep: allowed at most " + std::to_string(max_nesting_depth));
    }

    /// The entry of a JSON text at `position` inside one of its strings:
    /// the keys of the objects it lies in and its own ("Bar/Cross section";
    /// deal.II's {"value": ...} form and its name mangling undone), or ""
    /// outside a value.
    std::string json_entry_at(const std::string &text, const std::size_t position)
    {
      std::vector<std::string> keys{""}; // the key of each open object; the outermost has none
      std::string              key, string;
      char previous = 0; ///< the last character outside strings but white space ('"' after a string)
      const bool quoted = walk_json(
        text, position,
        [&](const std::size_t i) {
          if (text[i] == ':')
            key = string;
          else if (text[i] == '{')
            keys.push_back(key);
          else if (text[i] == '}' && keys.size() > 1)
            keys.pop_back();
          previous = text[i];
        },
        [&](const std::size_t start, const std::size_t i) {
          string   = text.substr(start, i - start);
          previous = '"';
        });
      // Inside a string, `previous` is what came before it: a value follows ':'.
      if (!quoted || previous != ':')
        return "";
      // deal.II's own fields of an entry are not part of its name.
      static const std::set<std::string> fields = {"value", "default_value", "documentation", "pattern",
                                                   "pattern_description", "actions"};
      std::string entry;
      for (const std::string &k : keys)
        entry += k.empty() ? "" : demangle(k) + "/";
      entry += fields.count(key) ? "" : demangle(key);
      if (!entry.empty() && entry.back() == '/')
        entry.pop_back();
      return entry;
    }

    /// A JSON or XML scene holds UTF-8 text only: else the parser's message
    /// would name neither the entry nor the line.
    void check_utf8(const std::string &path, const std::string &text, const bool json)
    {
      const std::size_t position = first_invalid_utf8(text);
      if (position == std::string::npos)
        return;
      const std::string entry = json ? json_entry_at(text, position) : "";
      const std::string line  = "line " + std::to_string(1 + std::count(text.begin(), text.begin() + position, '\n'));
      throw InputError("scene '" + shown(path) + "': " +
                       (entry.empty() ? line : "parameter '" + printable(entry) + "' (" + line + ")") +
                       " is not valid UTF-8 text: allowed, text in UTF-8 (a byte shown as \\xNN is not)");
    }

    /// A JSON or XML scene's text, read once and checked before the parser
    /// sees it.
    std::string checked_tree_text(const std::string &path, const bool json)
    {
      readable_file(path);
      std::ifstream      in(path, std::ios::binary);
      std::ostringstream read;
      read << in.rdbuf();
      const std::string text = read.str();
      check_nesting(path, text, json);
      check_utf8(path, text, json);
      return text;
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

  namespace
  {
    std::vector<ParameterOverride> &override_list()
    {
      static std::vector<ParameterOverride> overrides;
      return overrides;
    }

    bool overridden(const std::string &path)
    {
      return std::any_of(override_list().begin(), override_list().end(),
                         [&](const ParameterOverride &o) { return o.path == path; });
    }

    /// The overrides set on the text stage of a read, each on its declared entry.
    void apply_overrides(dealii::ParameterHandler &text, const std::vector<DeclaredEntry> &entries)
    {
      for (const ParameterOverride &o : override_list())
        {
          const auto entry =
            std::find_if(entries.begin(), entries.end(), [&](const DeclaredEntry &e) { return e.path() == o.path; });
          if (entry == entries.end())
            throw InputError("command line: --set '" + printable(o.path) +
                             "': no such parameter (nsm-bar --print-parameters lists them)");
          in_sections(text, *entry, [&] { text.set(entry->name, o.value); });
        }
    }
  } // namespace

  ParameterOverride parse_override(const std::string &text)
  {
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos || equals == 0 || text.find('/') > equals)
      throw InputError("command line: --set '" + printable(text) +
                       "' is not of the form \"Section/Entry=value\"");
    ParameterOverride o{text.substr(0, equals), text.substr(equals + 1)};
    // A scene file's "set Entry = value" drops the spaces around '='; on the
    // command line they would stay in the name (no such parameter) or the
    // value (which the record cannot hold), so they are named here.
    const auto trimmed = [](const std::string &t) {
      const std::size_t first = t.find_first_not_of(" \t");
      return first == std::string::npos ? std::string() : t.substr(first, t.find_last_not_of(" \t") - first + 1);
    };
    if (trimmed(o.path) != o.path || trimmed(o.value) != o.value)
      throw InputError("command line: --set '" + printable(text) + "' has white space around '=' or at the value's "
                       "ends, which the run's record cannot hold: write --set \"" + printable(trimmed(o.path)) + "=" +
                       printable(trimmed(o.value)) + "\"");
    return o;
  }

  void set_parameter_overrides(const std::vector<ParameterOverride> &overrides)
  {
    override_list() = overrides;
  }

  const std::vector<ParameterOverride> &parameter_overrides()
  {
    return override_list();
  }

  namespace
  {
    /// deal.II's "Line <n> of file <f>: No entry with name <x> was declared
    /// in the current subsection." said with the entry's full path, from the
    /// PRM text's subsections up to line n; other messages as they are. Both
    /// end with where the parameters are listed.
    /// deal.II's "Line <n> of file <f>: The line <text> could not be parsed
    /// ..." said with the file and line the text came from, without the text
    /// (an included file's content is not echoed: `include /etc/hostname`).
    std::string unparsed_line(const std::string &message, const std::vector<LineOrigin> &origins)
    {
      std::smatch match;
      if (!std::regex_search(message, match, std::regex(R"(Line <(\d+)>.*could not be parsed)")))
        return "";
      const unsigned long n = std::stoul(match[1]);
      if (n == 0 || n > origins.size())
        return "";
      const LineOrigin &o = origins[n - 1];
      return "line " + std::to_string(o.line) + " of '" + shown(o.file) +
             "' is not a 'set', 'include', 'subsection' or 'end' line";
    }

    std::string undeclared_entry(const std::string &message, const std::string &prm_text)
    {
      // deal.II's messages on unbalanced sections name no parameter.
      const bool        sections_unbalanced = message.find("'subsection' and 'end'") != std::string::npos ||
                                       message.find("no subsection to leave") != std::string::npos;
      const std::string hint = sections_unbalanced ? " (each 'subsection NAME' line needs one 'end' line after its "
                                                     "entries)" :
                                                     " (nsm-bar --print-parameters lists them)";
      std::smatch       match;
      if (prm_text.empty() ||
          !std::regex_search(message, match, std::regex(R"(Line <(\d+)>.*No entry with name <([^>]*)> was declared)")))
        return message + hint;
      const unsigned long      line = std::stoul(match[1]);
      std::vector<std::string> sections;
      std::istringstream       in(prm_text);
      std::string              text;
      std::smatch              words;
      for (unsigned long n = 1; n < line && std::getline(in, text); ++n)
        if (std::regex_match(text, words, std::regex(R"(\s*subsection\s+(.*?)\s*(#.*)?)")))
          sections.push_back(words[1]);
        else if (std::regex_match(text, std::regex(R"(\s*end\s*(#.*)?)")) && !sections.empty())
          sections.pop_back();
      std::string entry;
      for (const std::string &section : sections)
        entry += section + "/";
      return "line " + match[1].str() + ": no parameter '" + printable(entry + match[2].str()) + "'" + hint;
    }
  } // namespace

  namespace
  {
    /// Why `value` cannot be a scene value, or "": text only, valid UTF-8
    /// (deal.II's parameter tree and its JSON and XML are text), on one line
    /// (a checkpoint and a recorded scene hold one entry per line; a tab is
    /// white space and allowed).
    std::string unusable_text(const std::string &value)
    {
      if (!is_valid_utf8(value))
        return "is not valid UTF-8 text: allowed, text in UTF-8 (a byte shown as \\xNN is not)";
      std::string without_tabs = value;
      without_tabs.erase(std::remove(without_tabs.begin(), without_tabs.end(), '\t'), without_tabs.end());
      if (has_control_character(without_tabs))
        return "holds a control character (shown as \\xNN): allowed, one line of text";
      return "";
    }

    /// Whether deal.II's get_double or get_integer reads `value` for an
    /// entry of this pattern as its pattern accepts it: a subnormal number
    /// (below 2.2e-308 in magnitude) matches a Double pattern, but
    /// get_double refuses it (strtod's ERANGE).
    bool converts(const std::string &value, const std::string &pattern)
    {
      if (pattern.rfind("[Double", 0) == 0)
        return !scene_entries::outside_normal_range(value);
      errno = 0;
      if (pattern.rfind("[Integer", 0) == 0)
        std::strtol(value.c_str(), nullptr, 10);
      return errno != ERANGE;
    }

    /// For a number refused though within the range: why.
    std::string subnormal_note(const std::string &value, const std::string &pattern)
    {
      return pattern.rfind("[Double", 0) == 0 && dealii::Patterns::Double().match(value) && !converts(value, pattern) ?
               " (a number of magnitude below 2.2e-308, subnormal, is not: write 0 or a larger one)" :
               "";
    }
  } // namespace

  void read_scene_file(const std::string &path, dealii::ParameterHandler &prm)
  {
    const std::string extension = fs::path(path).extension().string();
    const bool        tree_format = extension == ".json" || extension == ".xml";
    std::stringstream       flat;
    std::vector<LineOrigin> origins; // of each line of a PRM text's flattened text
    if (tree_format)
      flat.str(checked_tree_text(path, extension == ".json"));
    else
      {
        std::vector<fs::path> chain;
        std::size_t           files = 0;
        flatten(path, chain, flat, files, origins);
      }

    // Every entry as text first: deal.II's own pattern errors name neither
    // the subsection nor the range in words.
    const std::vector<DeclaredEntry> entries = declared_entries(prm);
    dealii::ParameterHandler text;
    declare_as_text(text, entries);
    try
      {
        if (extension == ".json")
          text.parse_input_from_json(flat);
        else if (extension == ".xml")
          text.parse_input_from_xml(flat);
        else
          text.parse_input(flat, path);
      }
    catch (const dealii::ExceptionBase &e)
      {
        const std::string unparsed = unparsed_line(one_line_message(e), origins);
        throw InputError("scene '" + shown(path) + "': " +
                         (!unparsed.empty() ? unparsed :
                                              undeclared_entry(one_line_message(e), tree_format ? "" : flat.str())));
      }
    catch (const std::exception &e)
      {
        throw InputError("scene '" + shown(path) + "' cannot be parsed: " + e.what());
      }
    apply_overrides(text, entries);

    for (const DeclaredEntry &entry : entries)
      {
        std::string value;
        in_sections(text, entry, [&] { value = text.get(entry.name); });
        const std::string where = "scene '" + shown(path) + "': parameter '" + entry.path() + "' = " + printable(value);
        const std::string from_command_line = overridden(entry.path()) ? " (set by --set on the command line)" : "";
        if (const std::string why = unusable_text(value); !why.empty())
          throw InputError(where + " " + why + from_command_line);
        if (!dealii::Patterns::pattern_factory(entry.pattern)->match(value) || !converts(value, entry.pattern))
          throw InputError(where + " is out of range: allowed " + allowed_values(entry.pattern) +
                           subnormal_note(value, entry.pattern) + from_command_line);
        in_sections(prm, entry, [&] { prm.set(entry.name, value); });
      }
  }

  namespace
  {
    /// How the record reads `entry`'s value back when it is the only line
    /// in its subsections ("" if that line does not parse).
    std::string read_back_alone(const DeclaredEntry &entry)
    {
      dealii::ParameterHandler alone;
      in_sections(alone, entry, [&] { alone.declare_entry(entry.name, "", dealii::Patterns::Anything()); });
      std::string line;
      for (const std::string &section : entry.sections)
        line += "subsection " + section + "\n";
      line += "set " + entry.name + " = " + entry.value + "\n";
      for (std::size_t i = 0; i < entry.sections.size(); ++i)
        line += "end\n";
      try
        {
          alone.parse_input_from_string(line, "parameters.prm");
        }
      catch (const dealii::ExceptionBase &)
        {
          return "";
        }
      std::string value;
      in_sections(alone, entry, [&] { value = alone.get(entry.name); });
      return value;
    }
  } // namespace

  void check_record_reads_back(const dealii::ParameterHandler &prm, const std::string &record)
  {
    const std::vector<DeclaredEntry> entries = declared_entries(prm);
    dealii::ParameterHandler         text;
    declare_as_text(text, entries);
    bool parsed = true;
    try
      {
        text.parse_input_from_string(record, "parameters.prm");
      }
    catch (const dealii::ExceptionBase &)
      {
        parsed = false; // the entry to blame is found below, one at a time
      }
    for (const DeclaredEntry &entry : entries)
      {
        std::string value = entry.value;
        if (parsed)
          in_sections(text, entry, [&] { value = text.get(entry.name); });
        else
          value = read_back_alone(entry);
        if (value != entry.value)
          throw InputError("parameter '" + entry.path() + "' = '" + printable(entry.value) +
                           "' cannot be written to the run's record (parameters.prm) so that it reads back the "
                           "same (it reads back as '" + printable(value) +
                           "'): allowed, a value without '#', without a backslash at its end and without white "
                           "space at either end" + (overridden(entry.path()) ? " (set on the command line)" : ""));
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
