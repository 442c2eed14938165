// Reading a scene file: the file checks and the pattern checks, with
// messages that name the parameter's full path and its allowed values.
#pragma once

#include <string>
#include <vector>

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  /// Most nested includes of a PRM scene.
  constexpr std::size_t max_include_depth = 32;
  /// Most files a PRM scene may include in all (a chain may include one
  /// file many times).
  constexpr std::size_t max_included_files = 10000;
  /// Deepest nesting of a JSON or XML scene.
  constexpr std::size_t max_nesting_depth = 64;

  /// Reads the scene file `path` into `prm`, whose entries are declared with
  /// bounded patterns. The file must be a readable regular file. A PRM
  /// file's `include` lines (any file name, any white space) are replaced by
  /// the included texts, at most max_include_depth deep and never a file
  /// inside itself; JSON and XML are nested at most max_nesting_depth deep. It is parsed with every entry accepted as
  /// text, then each value is checked against its declared pattern, so that
  /// a rejection names the entry as Section/Subsection/Name and says its
  /// allowed values in words. Throws InputError.
  void read_scene_file(const std::string &path, dealii::ParameterHandler &prm);

  /// Checks that `record`, the PRM text a run writes as its record
  /// (parameters.prm), reads back with every entry of `prm` equal to its
  /// value: deal.II's PRM starts a comment at '#', joins a line ending in a
  /// backslash to the next and trims white space around a value, so a value
  /// holding one of these (given through --set, --output or a JSON or XML
  /// scene) would rerun another scene, or write into another folder. Throws
  /// InputError naming the first entry that does not read back.
  void check_record_reads_back(const dealii::ParameterHandler &prm, const std::string &record);

  /// A value given on the command line (`--set "Section/Entry=value"`), for
  /// the entry Section/Subsection/Name.
  struct ParameterOverride
  {
    std::string path;
    std::string value;
  };

  /// Parses "Section/Entry=value"; throws InputError naming the text.
  ParameterOverride parse_override(const std::string &text);

  /// The command line's overrides: every read_scene_file of this process
  /// applies them on top of the file, before the pattern checks, so that a
  /// bad value fails with the file's messages, and a study's rows, which
  /// read the scene again, see them too.
  void set_parameter_overrides(const std::vector<ParameterOverride> &overrides);
  const std::vector<ParameterOverride> &parameter_overrides();

  /// A declared entry: its subsections, its name, its default, its
  /// pattern's description and its documentation.
  struct DeclaredEntry
  {
    std::vector<std::string> sections;
    std::string              name;
    std::string              default_value;
    std::string              pattern;
    std::string              documentation;
    std::string              value; ///< as parsed (the default if the file did not set it)

    /// "Section/Subsection/Name".
    std::string path() const
    {
      std::string p;
      for (const std::string &s : sections)
        p += s + "/";
      return p + name;
    }
  };

  /// Every entry declared in `prm`, in ParameterHandler's order.
  std::vector<DeclaredEntry> declared_entries(const dealii::ParameterHandler &prm);

  /// A deal.II pattern description in words:
  /// "[Double 0...1 (inclusive)]" -> "a number in [0, 1]".
  std::string allowed_values(const std::string &pattern_description);

  /// A value to check against the declared pattern of the entry at
  /// `entry_path` ("Discretisation/Degree"); `parameter` gave the value.
  struct AllowedCheck
  {
    std::string entry_path, value, parameter;
  };

  /// Checks each value against its entry's declared pattern, the declared
  /// entries read once for all of them (nothing is read for no check);
  /// throws InputError naming the parameter, the entry and the allowed values.
  void require_allowed(const dealii::ParameterHandler &prm, const std::vector<AllowedCheck> &checks);
} // namespace nsm
