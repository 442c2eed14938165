#include <nsm/output/plots.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// Runs a program with these arguments, without a shell (no character of
    /// an argument is interpreted), its output to `log`; returns whether it
    /// exited with status 0.
    bool run_program(const std::vector<std::string> &arguments, const std::string &log)
    {
      std::vector<char *> argv;
      for (const std::string &a : arguments)
        argv.push_back(const_cast<char *>(a.c_str()));
      argv.push_back(nullptr);
      posix_spawn_file_actions_t actions;
      posix_spawn_file_actions_init(&actions);
      // A new file: never one a link points to.
      posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                       O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW, 0644);
      posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
      pid_t      pid;
      const bool spawned =
        posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) == 0;
      posix_spawn_file_actions_destroy(&actions);
      int status = 0;
      return spawned && waitpid(pid, &status, 0) == pid && WIFEXITED(status) &&
             WEXITSTATUS(status) == 0;
    }

    /// A Python error for a full disk (ENOSPC) or a file size limit (EFBIG).
    bool out_of_space(const std::string &error)
    {
      return error.find("[Errno 28]") != std::string::npos || error.find("[Errno 27]") != std::string::npos;
    }
  } // namespace

  std::vector<std::string> make_plots(const Scene::Contact &contact, const std::string &directory)
  {
    std::ostringstream gap;
    gap.precision(17);
    gap << contact.gap;
    const std::string log_path = directory + "/plots.log";
    std::error_code   error;
    std::filesystem::remove(log_path, error);
    // The directory as an absolute path, after "--": a name that starts with
    // '-' is never read as an option.
    const std::string absolute = std::filesystem::absolute(directory).string();
    const bool ok = run_program({NSM_PYTHON, NSM_PLOT_SCRIPT, "--gap", gap.str(), "--", absolute}, log_path);
    std::vector<std::string> files;
    std::string              last;
    std::ifstream            log(log_path);
    for (std::string line; std::getline(log, line); last = line)
      if (line.rfind("wrote ", 0) == 0)
        {
          // The script names the files under the absolute path; the run
          // names them under `directory`, as it wrote the others.
          std::string file = line.substr(6);
          if (file.rfind(absolute + "/", 0) == 0)
            file = directory + file.substr(absolute.size());
          files.push_back(file);
        }
    // The log goes with the failed run's staging directory: its last line is kept.
    if (!ok && out_of_space(last))
      throw OutputError("the plots could not be written whole (disk full or file size limit?): " + last);
    if (!ok)
      throw NumericalError("the plotting script failed: " + last);
    files.push_back(log_path);
    return files;
  }
} // namespace nsm
