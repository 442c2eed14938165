#include <nsm/base/csv.h>
#include <nsm/output/output_directory.h>
#include <nsm/base/errors.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>

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

    /// Whether the target may be replaced: missing, empty, or a run's output.
    void check_target(const fs::path &target, const std::string &name)
    {
      std::error_code error;
      const fs::file_status status = fs::status(target, error);
      if (!fs::exists(status))
        return;
      if (!fs::is_directory(status))
        throw directory_error(name, "exists and is not a directory");
      if (fs::is_empty(target, error) || fs::exists(target / OutputDirectory::manifest, error))
        return;
      throw directory_error(name,
                            "holds files that no nsm-bar run wrote (it has no " +
                              std::string(OutputDirectory::manifest) +
                              "): choose a new, an empty or an earlier output directory");
    }

    /// Swaps two directories in one step; the fallback (a file system
    /// without RENAME_EXCHANGE) leaves a moment with no target at all, never
    /// one with a mixture.
    void swap_directories(const fs::path &a, const fs::path &b)
    {
      if (renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0)
        return;
      const fs::path aside = a.string() + ".old";
      fs::rename(b, aside);
      fs::rename(a, b);
      fs::rename(aside, a);
    }
  } // namespace

  OutputDirectory::OutputDirectory(const std::string &target)
  {
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
    const std::string prefix = "." + path.filename().string() + ".nsm-bar-";
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

  std::vector<std::string> OutputDirectory::commit(const std::vector<std::string> &files)
  {
    std::vector<std::string> final_paths;
    const std::string        prefix = staging_ + "/";
    write_atomically(prefix + manifest, [&](std::ostream &out) {
      for (const std::string &f : files)
        out << f.substr(prefix.size()) << '\n';
    });
    for (const std::string &f : files)
      final_paths.push_back(target_ + "/" + f.substr(prefix.size()));
    try
      {
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
