// The output directory of one run, written whole or not at all.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace nsm
{
  /// The folders of `path` that do not exist yet, deepest first: those
  /// creating it makes, and that a failure removes again (if still empty).
  std::vector<std::string> missing_folders(std::filesystem::path path);

  /// Files go into a hidden staging sibling of `Output/Directory`, which
  /// commit() swaps in for it in one rename, so the directory holds either
  /// the previous complete output or the new one, never a mixture, and never
  /// a file of an earlier run listed as new. A run that fails, or is killed,
  /// leaves the previous output as it was; its staging directory is removed
  /// at once, or by the next run into the same directory. No file of the
  /// user's is ever removed: of an earlier output only the files its
  /// manifest lists go, by name.
  class OutputDirectory
  {
  public:
    /// Checks the target and creates the staging directory. The target must
    /// be missing, empty, or an earlier run's output (it holds the manifest),
    /// so that no file nsm-bar did not write is ever replaced. Throws
    /// InputError naming Output/Directory.
    ///
    /// `default_of`, if not empty, is the scene file (its canonical path)
    /// whose default folder (output/NAME) the target is: the manifest records
    /// it, and a target holding an output that another scene file made, or
    /// that was made under an explicit Output/Directory, is refused, so that
    /// two scene files with one NAME (a/x.prm and b/x.prm, x.prm and x.json)
    /// never replace each other's output.
    explicit OutputDirectory(const std::string &target, const std::string &default_of = "");
    ~OutputDirectory();
    OutputDirectory(const OutputDirectory &) = delete;
    OutputDirectory &operator=(const OutputDirectory &) = delete;

    /// Where this run writes its files.
    const std::string &staging() const { return staging_; }

    /// Where `files` (paths under staging()) will be once committed.
    std::vector<std::string> final_paths(const std::vector<std::string> &files) const;

    /// Writes the manifest of `files` (paths under staging()), and after them
    /// the `notes`, each on a line that starts with "/ " (no file's name
    /// can), removes from the staging directory what the manifest does not
    /// list (a plot stopped half-way), swaps it in and removes the files of
    /// the previous output that its manifest lists; a file of the user's that
    /// appeared meanwhile is moved back into the directory. Returns the
    /// files' final paths. Throws OutputError, also when another run
    /// replaced the directory since this one began (two runs into one
    /// folder at once): the other run's output stays, this one's is not
    /// kept.
    std::vector<std::string> commit(const std::vector<std::string> &files,
                                    const std::vector<std::string> &notes = {});

    /// The file every nsm-bar output directory holds: the files it lists.
    static constexpr const char *manifest = "nsm-bar.manifest";
    /// The manifest's note that names the scene file whose default folder
    /// the directory is, followed by its canonical path.
    static constexpr const char *default_folder_note = "/ default folder of ";

  private:
    /// Checks that the target is still what this run found (no other run's
    /// output, no foreign file) and swaps the staging directory in; returns
    /// whether a previous output was swapped out (to the staging name, locked
    /// in `previous_lock`). Throws OutputError, or filesystem_error.
    bool swap_in(int &previous_lock);

    std::string              target_;
    std::string              default_of_; ///< the scene file whose default folder this is, or ""
    /// The target's device and inode when this run began ({0, 0}: it did not
    /// exist): a swap finds another run's output by a change of either.
    std::pair<unsigned long, unsigned long> identity_{0, 0};
    std::string              staging_;
    int                      lock_ = -1; ///< the staging directory, locked while this run lives
    std::vector<std::string> created_parents_; ///< made for the target, deepest first
    bool                     committed_ = false;
  };

  /// The scene file whose default folder `target` holds the output of, as
  /// its manifest records it (printable); "" if it records none.
  std::string default_folder_owner(const std::string &target);

  /// Removes from `previous` (an earlier output, taken out of `target`) the
  /// files its manifest lists and the manifest, then moves whatever is left
  /// (a user's file) back into `target` under the same name; what cannot go
  /// back (its name is taken) stays in `previous`, renamed to a visible
  /// sibling of `target` whose name is returned (empty if nothing stayed).
  std::string discard_previous_output(const std::string &previous, const std::string &target);
} // namespace nsm
