#include <nsm/base/csv.h>
#include <nsm/output/output_directory.h>
#include <nsm/base/errors.h>
#include <nsm/base/text.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <regex>
#include <set>

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace nsm
{
  namespace
  {
    namespace fs = std::filesystem;

    /// The longest name of one folder (Linux's NAME_MAX).
    constexpr std::size_t max_name_bytes = 255;
    /// PATH_MAX (4096) less what a run puts under the directory's parent: its
    /// staging sibling's name (about 60 bytes) and the longest file name it
    /// writes there (field_NNN_snapshots/snapshot_NNNN.vtu.partial), with
    /// room to spare for the plotting script's absolute paths.
    constexpr std::size_t max_path_bytes = 3800;

    InputError directory_error(const std::string &target, const std::string &why)
    {
      return InputError("parameter 'Output/Directory' = '" + printable(target) + "' " + why);
    }

    /// A name of one entry of the directory itself: no folder part, not "."
    /// or "..". A manifest line that is not one (an edited manifest) names
    /// nothing the run removes.
    bool plain_name(const std::string &name)
    {
      return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos;
    }

    /// The manifest's lines; none if it is not a regular file.
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

    /// The files a folder of VTK snapshots may hold, by name: the manifest
    /// lists it as "FOLDER/ (N snapshots)", and the run wrote
    /// snapshot_0000.vtu ... snapshot_{N-1}.vtu. nullopt if it is not listed.
    std::optional<std::set<std::string>> listed_folder(const std::set<std::string> &listed,
                                                       const std::string           &folder)
    {
      if (!plain_name(folder))
        return std::nullopt;
      for (const std::string &line : listed)
        {
          unsigned long count = 0;
          char          rest[16];
          if (line.rfind(folder + "/ (", 0) != 0 ||
              std::sscanf(line.c_str() + folder.size() + 3, "%lu snapshot%15s", &count, rest) != 2 ||
              count > 1000000)
            continue;
          std::set<std::string> names;
          for (unsigned long j = 0; j < count; ++j)
            {
              char name[48];
              std::snprintf(name, sizeof name, "snapshot_%04lu.vtu", j);
              names.insert(name);
            }
          return names;
        }
      return std::nullopt;
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
      if (listed.empty() && fs::exists(target / "study.scene", error))
        throw directory_error(name, "holds a study's output (study.scene), which a scene's run does not replace: "
                                    "choose a new, an empty or an earlier run's output directory");
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
          if (entry.is_directory())
            {
              const auto names = listed_folder(listed, file);
              if (!names)
                throw foreign(file);
              for (const auto &inner : fs::directory_iterator(entry.path(), error))
                if (inner.is_symlink() || !inner.is_regular_file() ||
                    !names->count(inner.path().filename().string()))
                  throw foreign(file + "/" + inner.path().filename().string());
              continue;
            }
          if (!listed.count(file) || !entry.is_regular_file())
            throw foreign(file);
        }
    }

    /// A default folder (output/NAME) holds only its own scene file's output.
    void check_default_owner(const fs::path &target, const std::string &name, const std::string &scene)
    {
      std::error_code error;
      if (scene.empty() || !fs::is_regular_file(fs::symlink_status(target / OutputDirectory::manifest, error)))
        return;
      const std::string owner = default_folder_owner(target.string());
      if (owner == printable(scene))
        return;
      throw InputError("parameter 'Output/Directory' is not set, and its default '" + printable(name) + "' holds " +
                       (owner.empty() ? std::string("an output that records no default folder (written under an "
                                                    "explicit Output/Directory, or by an older nsm-bar)") :
                                        "the output of the scene file '" + owner + "'") +
                       ", not of '" + printable(scene) +
                       "': set Output/Directory (or --output) for this scene, so that neither replaces the other");
    }

    /// The device and inode of `path`, {0, 0} if it does not exist.
    std::pair<unsigned long, unsigned long> identity(const fs::path &path)
    {
      struct stat status{};
      if (lstat(path.c_str(), &status) != 0)
        return {0, 0};
      return {static_cast<unsigned long>(status.st_dev), static_cast<unsigned long>(status.st_ino)};
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

    /// A name no other run on any machine or PID namespace picks: the
    /// process number and 64 random bits.
    std::string unique_token()
    {
      std::random_device random;
      char               text[48];
      std::snprintf(text, sizeof text, "%ld-%08x%08x", static_cast<long>(getpid()), random(), random());
      return text;
    }

    /// An exclusive lock on a directory (flock: held by the open file, across
    /// renames, released when its process ends, however it ends); -1 if it is
    /// held elsewhere or the directory cannot be opened. A link is not
    /// followed unless `follow_link`.
    int lock_directory(const fs::path &directory, const bool wait, const bool follow_link = false)
    {
      const int fd = open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC | (follow_link ? 0 : O_NOFOLLOW));
      if (fd < 0)
        return -1;
      if (flock(fd, LOCK_EX | (wait ? 0 : LOCK_NB)) != 0)
        {
          close(fd);
          return -1;
        }
      return fd;
    }

    /// An exclusive flock on a folder (its link followed) for the guard's
    /// life; none if the folder cannot be opened for reading, and the guarded
    /// step then goes on unguarded.
    class FolderLock
    {
    public:
      explicit FolderLock(const fs::path &folder)
        : fd_(lock_directory(folder, true, true))
      {}
      ~FolderLock()
      {
        if (fd_ >= 0)
          close(fd_);
      }
      FolderLock(const FolderLock &) = delete;
      FolderLock &operator=(const FolderLock &) = delete;

    private:
      int fd_;
    };

    /// Moves each entry under `from` back to the same place under `to`, never
    /// over an entry there; returns whether `from` is empty afterwards.
    bool move_back(const fs::path &from, const fs::path &to)
    {
      std::error_code error;
      std::vector<fs::path> entries;
      for (const auto &entry : fs::directory_iterator(from, error))
        entries.push_back(entry.path());
      bool emptied = !error;
      for (const fs::path &entry : entries)
        {
          const fs::path destination = to / entry.filename();
          if (fs::is_directory(fs::symlink_status(entry, error)) &&
              fs::is_directory(fs::symlink_status(destination, error)))
            {
              if (move_back(entry, destination))
                fs::remove(entry, error);
              else
                emptied = false;
            }
          else if (renameat2(AT_FDCWD, entry.c_str(), AT_FDCWD, destination.c_str(), RENAME_NOREPLACE) != 0)
            emptied = false;
        }
      return emptied;
    }

    /// Removes `folder` and its subfolders if they hold no file; returns
    /// whether it is gone.
    bool remove_empty_folders(const fs::path &folder)
    {
      std::error_code       error;
      std::vector<fs::path> inner;
      for (const auto &entry : fs::directory_iterator(folder, error))
        if (entry.is_directory() && !entry.is_symlink())
          inner.push_back(entry.path());
      for (const fs::path &f : inner)
        remove_empty_folders(f);
      return fs::remove(folder, error);
    }

    /// Swaps two directories in one step. The fallback (a file system without
    /// RENAME_EXCHANGE) passes the target (locked by the caller) through an
    /// aside sibling: a run killed between its renames leaves it there, and
    /// the next run puts it back (or discards it, if the new output went in).
    void swap_directories(const fs::path &staging, const fs::path &target, const std::string &aside)
    {
      if (renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0)
        return;
      fs::rename(target, aside);
      fs::rename(staging, target);
      fs::rename(aside, staging);
    }

    /// Staging and aside directories of runs that no longer hold their lock
    /// (killed ones), by their exact names: a staging directory is removed
    /// (one that holds a manifest, an output, is discarded by it); an aside
    /// one (the target's previous output, taken out by a run killed half-way
    /// through its fallback swap) goes back in place, or is discarded if the
    /// new output went in.
    void clear_dead_siblings(const fs::path &parent, const std::string &prefix, const fs::path &target)
    {
      std::error_code       error;
      std::vector<fs::path> siblings;
      const std::regex      ours(std::regex_replace(prefix, std::regex(R"([.\\])"), R"(\$&)") +
                                 R"(((run|aside)-\d+-[0-9a-f]{16}|\d+))");
      for (const auto &entry : fs::directory_iterator(parent, error))
        if (std::regex_match(entry.path().filename().string(), ours))
          siblings.push_back(entry.path());
      for (const fs::path &sibling : siblings)
        {
          const int lock = lock_directory(sibling, false);
          if (lock < 0)
            continue; // a live run's, or not a directory
          const bool aside = sibling.filename().string().rfind(prefix + "aside-", 0) == 0;
          if (aside && !fs::exists(fs::symlink_status(target, error)))
            fs::rename(sibling, target, error);
          else if (aside || fs::exists(fs::symlink_status(sibling / OutputDirectory::manifest, error)))
            discard_previous_output(sibling.string(), target.string()); // an output: its own files go
          else
            fs::remove_all(sibling, error); // a killed run's half-written files
          close(lock);
        }
    }

    /// Names no file system takes are refused before any work.
    void check_name_lengths(const fs::path &path, const std::string &target)
    {
      std::error_code   error;
      const std::size_t bytes = fs::absolute(path, error).string().size();
      if (bytes > max_path_bytes)
        throw directory_error(target.substr(0, 60) + "...", "is " + std::to_string(bytes) +
                                                              " bytes long as an absolute path: allowed at most " +
                                                              std::to_string(max_path_bytes));
      for (const fs::path &part : path)
        if (part.string().size() > max_name_bytes)
          throw directory_error(target.size() > 300 ? target.substr(0, 60) + "..." : target,
                                "has a folder name of " + std::to_string(part.string().size()) +
                                  " bytes: allowed at most " + std::to_string(max_name_bytes));
    }
  } // namespace

  std::string default_folder_owner(const std::string &target)
  {
    const std::string note = OutputDirectory::default_folder_note;
    for (const std::string &line : listed_files(fs::path(target) / OutputDirectory::manifest))
      if (line.rfind(note, 0) == 0)
        return line.substr(note.size());
    return "";
  }

  std::string discard_previous_output(const std::string &previous, const std::string &target)
  {
    const fs::path              folder(previous);
    const std::set<std::string> listed = listed_files(folder / OutputDirectory::manifest);
    std::error_code             error;
    for (const std::string &line : listed)
      {
        if (line.rfind("/ ", 0) == 0 || line.empty())
          continue; // a note
        const std::size_t slash = line.find("/ (");
        if (slash == std::string::npos)
          {
            if (plain_name(line) && line != OutputDirectory::manifest &&
                fs::is_regular_file(fs::symlink_status(folder / line, error)))
              fs::remove(folder / line, error);
            continue;
          }
        const std::string snapshots = line.substr(0, slash);
        if (const auto names = listed_folder(listed, snapshots))
          {
            for (const std::string &name : *names)
              if (fs::is_regular_file(fs::symlink_status(folder / snapshots / name, error)))
                fs::remove(folder / snapshots / name, error);
            fs::remove(folder / snapshots, error); // only if empty
          }
      }
    fs::remove(folder / OutputDirectory::manifest, error);
    // What is left is the user's: it goes back into the directory. A file
    // made meanwhile through a handle on the old folder goes too (a few
    // passes); empty folders are removed one by one, never a whole tree.
    for (int pass = 0; pass < 3; ++pass)
      if (fs::remove(folder, error) || (move_back(folder, target) && remove_empty_folders(folder)))
        return "";
    const std::string kept = target + ".files-kept-" + unique_token();
    fs::rename(folder, kept, error);
    return error ? previous : kept;
  }

  OutputDirectory::OutputDirectory(const std::string &target, const std::string &default_of)
    : default_of_(default_of)
  {
    if (has_control_character(target))
      throw directory_error(target, "holds a control character: allowed, a path without them");
    fs::path path = fs::path(target).lexically_normal();
    if (path.filename().empty())
      path = path.parent_path();
    if (path.filename() == "." || path.filename() == "..")
      throw directory_error(target, "must end in a directory name (not . or ..): it is "
                                    "replaced whole at the end of the run");
    check_name_lengths(path, target);
    fs::path parent = path.parent_path();
    if (parent.empty())
      parent = ".";
    const std::string prefix = staging_prefix(path.filename().string());
    std::error_code   error;
    if (fs::is_directory(parent, error))
      clear_dead_siblings(parent, prefix, path);
    // Noted before the checks: an output swapped in after them is another run's.
    identity_ = identity(path);
    check_target(path, target);
    check_default_owner(path, target, default_of_);
    created_parents_ = missing_folders(parent);
    fs::create_directories(parent, error);
    try
      {
        if (error)
          throw directory_error(target, "cannot be created: " + error.message());
        // Locked as soon as made; a run that took it for a dead one's in
        // between removed it, and the next name is tried.
        for (int attempt = 0; attempt < 8 && lock_ < 0; ++attempt)
          {
            staging_ = (parent / (prefix + "run-" + unique_token())).string();
            if (!fs::create_directory(staging_, error) || error)
              throw directory_error(target, "cannot be written: " +
                                              (error ? error.message() : std::string("unknown error")));
            lock_ = lock_directory(staging_, false);
          }
        if (lock_ < 0)
          throw directory_error(target, "cannot be written: its staging directory cannot be locked");
      }
    catch (...)
      {
        for (const std::string &folder : created_parents_)
          fs::remove(folder, error);
        throw;
      }
    target_ = path.string();
  }

  std::vector<std::string> missing_folders(std::filesystem::path path)
  {
    std::vector<std::string> missing;
    std::error_code          error;
    for (; !path.empty() && path != path.root_path() && !fs::exists(fs::symlink_status(path, error));
         path = path.parent_path())
      missing.push_back(path.string());
    return missing;
  }

  OutputDirectory::~OutputDirectory()
  {
    // Unlocked first: under a tight limit on open files (ulimit -n 4) the
    // removal needs the lock's descriptor.
    if (lock_ >= 0)
      close(lock_);
    std::error_code error;
    if (!committed_)
      {
        fs::remove_all(staging_, error);
        // Only the folders this run made, and only if they stayed empty.
        for (const std::string &folder : created_parents_)
          fs::remove(folder, error);
      }
  }

  namespace
  {
    /// Removes from `staging` what `listed` (the manifest's lines) does not
    /// name: a plot or a file a stopped stage left half-written.
    void prune_unlisted(const fs::path &staging, const std::set<std::string> &listed)
    {
      std::error_code       error;
      std::vector<fs::path> unlisted;
      for (const auto &entry : fs::directory_iterator(staging, error))
        {
          const std::string name = entry.path().filename().string();
          if (name != OutputDirectory::manifest && !listed.count(name) &&
              !(entry.is_directory() && listed_folder(listed, name)))
            unlisted.push_back(entry.path());
        }
      for (const fs::path &path : unlisted)
        fs::remove_all(path, error);
    }
  } // namespace

  std::vector<std::string> OutputDirectory::final_paths(const std::vector<std::string> &files) const
  {
    std::vector<std::string> paths;
    for (const std::string &f : files)
      paths.push_back(target_ + "/" + f.substr(staging_.size() + 1));
    return paths;
  }

  bool OutputDirectory::swap_in(int &previous_lock)
  {
    if (identity(target_) != identity_)
      throw OutputError("another run wrote its output into " + printable(target_) +
                        " while this one ran: that output is kept, and this run's is not (give each run a "
                        "directory of its own: Output/Directory or --output)");
    // Checked again: another run may have written into the directory since
    // this one began (a study writes in place).
    try
      {
        check_target(target_, target_);
      }
    catch (const InputError &e)
      {
        throw OutputError(std::string(e.what()) + " (it changed during the run); the new output is not kept");
      }
    const fs::path    parent = fs::path(staging_).parent_path();
    const std::string aside =
      (parent / (staging_prefix(fs::path(target_).filename().string()) + "aside-" + unique_token())).string();
    if (!fs::exists(fs::symlink_status(target_)))
      {
        fs::rename(staging_, target_);
        return false;
      }
    // Locked until its files are gone: no other run takes it, at the staging
    // name after the swap, for a dead run's.
    previous_lock = lock_directory(target_, true);
    swap_directories(staging_, target_, aside);
    return true;
  }

  std::vector<std::string> OutputDirectory::commit(const std::vector<std::string> &files,
                                                   const std::vector<std::string> &notes)
  {
    std::set<std::string>    listed;
    const std::string        prefix = staging_ + "/";
    write_atomically(prefix + manifest, [&](std::ostream &out) {
      for (const std::string &f : files)
        {
          out << f.substr(prefix.size()) << '\n';
          listed.insert(f.substr(prefix.size()));
        }
      if (!default_of_.empty())
        out << default_folder_note << printable(default_of_) << '\n';
      for (const std::string &note : notes)
        out << "/ " << printable(note) << '\n';
    });
    prune_unlisted(staging_, listed);
    const std::vector<std::string> paths = final_paths(files);
    int                            previous_lock = -1;
    bool                           had_previous;
    {
      // The check that no other run swapped its output in meanwhile and this
      // run's swap are one step for every run into the parent folder.
      const FolderLock parent_guard(fs::path(staging_).parent_path());
      try
        {
          had_previous = swap_in(previous_lock);
        }
      catch (const fs::filesystem_error &e)
        {
          if (previous_lock >= 0)
            close(previous_lock);
          throw OutputError("cannot move the new output into " + printable(target_) + ": " + e.what());
        }
    }
    committed_ = true;
    // The previous output, if any, now at the staging name: its own files go,
    // a file of the user's that appeared after the last check goes back.
    if (had_previous)
      {
        const std::string kept = discard_previous_output(staging_, target_);
        if (previous_lock >= 0)
          close(previous_lock);
        if (!kept.empty())
          throw OutputError("the new output is in " + printable(target_) + ", but files that appeared there during "
                            "the run could not go back beside it (their names are taken): they are in " +
                            printable(kept));
      }
    return paths;
  }
} // namespace nsm
