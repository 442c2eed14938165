#include <nsm/base/csv.h>
#include <nsm/output/output_directory.h>
#include <nsm/base/errors.h>
#include <nsm/base/text.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>

#include <fcntl.h>
#include <unistd.h>

namespace nsm
{
  namespace
  {
    namespace fs = std::filesystem;

    InputError directory_error(const std::string &target, const std::string &why)
    {
      return InputError("parameter 'Output/Directory' = '" + target + "' " + why);
    }

    /// Staging directories of runs that no longer exist (killed ones).
    void remove_stale_staging(const fs::path &parent, const std::string &prefix)
    {
      std::error_code error;
      for (const auto &entry : fs::directory_iterator(parent, error))
        {
          const std::string name = entry.path().filename().string();
          if (name.rfind(prefix, 0) != 0)
            continue;
          const pid_t pid = std::atoi(name.c_str() + prefix.size());
          if (pid > 0 && kill(pid, 0) != 0 && errno == ESRCH)
            fs::remove_all(entry.path(), error);
        }
    }

    /// The files a manifest lists; none if it is not a regular file.
    std::set<std::string> listed_files(const fs::path &manifest)
    {
      std::set<std::string> listed;
      std::error_code       error;
      if (!fs::is_regular_file(fs::symlink_status(manifest, error)))
        return listed;
      std::ifstream in(manifest);
      for (std::string line; std::getline(in, line);)
        listed.insert(line);
      return listed;
    }

    /// A folder of files the manifest lists as "FOLDER/ (...)" (the VTK
    /// snapshots).
    bool listed_folder(const std::set<std::string> &listed, const std::string &folder)
    {
      return std::any_of(listed.begin(), listed.end(),
                         [&](const std::string &line) { return line.rfind(folder + "/", 0) == 0; });
    }

    /// A folder that holds regular files only (no link, no subfolder).
    bool only_regular_files(const fs::path &folder)
    {
      std::error_code error;
      for (const auto &entry : fs::directory_iterator(folder, error))
        if (entry.is_symlink() || !entry.is_regular_file())
          return false;
      return !error;
    }

    /// Whether the target may be replaced: missing, empty, or exactly an
    /// earlier run's output, the regular files its manifest lists and the
    /// manifest itself. Anything else is the user's: the run is refused
    /// before it starts, and nothing of it is ever removed.
    void check_target(const fs::path &target, const std::string &name)
    {
      std::error_code       error;
      const fs::file_status link = fs::symlink_status(target, error);
      if (fs::is_symlink(link))
        throw directory_error(name, "is a symbolic link: the output is never written through a link");
      if (!fs::exists(link))
        return;
      if (!fs::is_directory(link))
        throw directory_error(name, "exists and is not a directory");
      if (fs::is_empty(target, error))
        return;
      const std::set<std::string> listed = listed_files(target / OutputDirectory::manifest);
      if (listed.empty())
        throw directory_error(name, "holds files that no nsm-bar run wrote (it has no " +
                                      std::string(OutputDirectory::manifest) +
                                      " file): choose a new, an empty or an earlier output directory");
      const auto foreign = [&](const std::string &file) {
        return directory_error(name, "holds '" + printable(file) + "', which its " +
                                       std::string(OutputDirectory::manifest) +
                                       " does not list as a file an nsm-bar run wrote: choose a new, an "
                                       "empty or an earlier output directory");
      };
      fs::directory_iterator entries(target, error);
      if (error)
        throw directory_error(name, "cannot be read: " + error.message());
      for (const auto &entry : entries)
        {
          const std::string file = entry.path().filename().string();
          if (file == OutputDirectory::manifest)
            continue;
          if (entry.is_symlink())
            throw foreign(file);
          if (entry.is_directory() && listed_folder(listed, file) && only_regular_files(entry.path()))
            continue;
          if (!listed.count(file) || !entry.is_regular_file())
            throw foreign(file);
        }
    }

    /// A short, stable name for the target's staging siblings (FNV-1a), so
    /// that a target name of up to NAME_MAX characters still has one.
    std::string staging_prefix(const std::string &name)
    {
      std::uint64_t hash = 14695981039346656037ull;
      for (const char c : name)
        hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
      char text[32];
      std::snprintf(text, sizeof text, ".nsm-bar-%016llx-", static_cast<unsigned long long>(hash));
      return text;
    }

    /// Swaps two directories in one step; the fallback (a file system
    /// without RENAME_EXCHANGE) leaves a moment with no target at all, never
    /// one with a mixture.
    void swap_directories(const fs::path &a, const fs::path &b)
    {
      if (renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0)
        return;
      // Not a staging name: a stale staging's removal must never take it.
      const fs::path aside = b.parent_path() / (".nsm-bar-aside-" + std::to_string(getpid()));
      fs::rename(b, aside);
      fs::rename(a, b);
      fs::rename(aside, a);
    }
  } // namespace

  OutputDirectory::OutputDirectory(const std::string &target)
  {
    if (has_control_character(target))
      throw directory_error(printable(target), "holds a control character: allowed, a path without them");
    fs::path path = fs::path(target).lexically_normal();
    if (path.filename().empty())
      path = path.parent_path();
    if (path.filename() == "." || path.filename() == "..")
      throw directory_error(target, "must end in a directory name (not . or ..): it is "
                                    "replaced whole at the end of the run");
    check_target(path, target);
    fs::path parent = path.parent_path();
    if (parent.empty())
      parent = ".";
    std::error_code error;
    fs::create_directories(parent, error);
    if (error)
      throw directory_error(target, "cannot be created: " + error.message());
    const std::string prefix = staging_prefix(path.filename().string());
    remove_stale_staging(parent, prefix);
    staging_ = (parent / (prefix + std::to_string(getpid()))).string();
    fs::remove_all(staging_, error);
    if (!fs::create_directory(staging_, error) || error)
      throw directory_error(target, "cannot be written: " +
                                      (error ? error.message() : std::string("unknown error")));
    target_ = path.string();
  }

  OutputDirectory::~OutputDirectory()
  {
    std::error_code error;
    if (!committed_)
      fs::remove_all(staging_, error);
  }

  std::vector<std::string> OutputDirectory::commit(const std::vector<std::string> &files,
                                                   const std::vector<std::string> &notes)
  {
    std::vector<std::string> final_paths;
    const std::string        prefix = staging_ + "/";
    write_atomically(prefix + manifest, [&](std::ostream &out) {
      for (const std::string &f : files)
        out << f.substr(prefix.size()) << '\n';
      for (const std::string &note : notes)
        out << "/ " << printable(note) << '\n';
    });
    for (const std::string &f : files)
      final_paths.push_back(target_ + "/" + f.substr(prefix.size()));
    try
      {
        // Checked again: another run may have written into the directory
        // since this one began (a study writes in place).
        try
          {
            check_target(target_, target_);
          }
        catch (const InputError &e)
          {
            throw OutputError(std::string(e.what()) + " (it changed during the run); the new output is not kept");
          }
        if (fs::exists(target_))
          swap_directories(staging_, target_);
        else
          fs::rename(staging_, target_);
      }
    catch (const fs::filesystem_error &e)
      {
        throw OutputError("cannot move the new output into " + target_ + ": " + e.what());
      }
    committed_ = true;
    std::error_code error;
    fs::remove_all(staging_, error); // the previous output, if any
    return final_paths;
  }
} // namespace nsm
