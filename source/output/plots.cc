#include <nsm/base/csv.h>
#include <nsm/base/interruption.h>
#include <nsm/base/text.h>
#include <nsm/output/plots.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace nsm
{
  namespace
  {
    /// How often the wait for the script looks for a stop signal: a Ctrl-C
    /// is answered within this time.
    constexpr std::chrono::milliseconds stop_poll_interval(20);
    /// How long a script asked to end (SIGTERM) has before it is killed.
    constexpr std::chrono::seconds end_grace(5);
    /// The script's last line when it drew every plot (plot_results.py).
    constexpr const char *done_line = "plots done";

    enum class ProgramEnd
    {
      succeeded,
      failed,
      not_started,
      stopped
    };

    /// Waits for `pid`; a stop signal to this process that arrives meanwhile
    /// ends it (SIGTERM to its group) and is reported as `stopped`.
    ProgramEnd wait_for(const pid_t pid)
    {
      const int signals_before = stop_signals_received();
      int       status         = 0;
      for (;;)
        {
          const pid_t done = waitpid(pid, &status, WNOHANG);
          if (done == pid)
            break;
          if (done < 0)
            return ProgramEnd::failed;
          if (stop_signals_received() != signals_before)
            {
              kill(-pid, SIGTERM);
              const auto deadline = std::chrono::steady_clock::now() + end_grace;
              while (waitpid(pid, &status, WNOHANG) == 0)
                {
                  if (std::chrono::steady_clock::now() >= deadline)
                    kill(-pid, SIGKILL); // it ignores SIGTERM
                  std::this_thread::sleep_for(stop_poll_interval);
                }
              return ProgramEnd::stopped;
            }
          std::this_thread::sleep_for(stop_poll_interval);
        }
      return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? ProgramEnd::succeeded : ProgramEnd::failed;
    }

    /// Runs a program with these arguments, without a shell (no character of
    /// an argument is interpreted), in a process group of its own (a
    /// terminal's Ctrl-C reaches this process alone), its output to `log`.
    ProgramEnd run_program(const std::vector<std::string> &arguments, const std::string &log)
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
      posix_spawnattr_t attributes;
      posix_spawnattr_init(&attributes);
      posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
      posix_spawnattr_setpgroup(&attributes, 0);
      pid_t      pid;
      const bool spawned = posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ) == 0;
      posix_spawnattr_destroy(&attributes);
      posix_spawn_file_actions_destroy(&actions);
      return spawned ? wait_for(pid) : ProgramEnd::not_started;
    }

    /// The plots the log names ("wrote PATH"), under `directory`; and its last line.
    std::vector<std::string> plots_written(const std::string &log_path, const std::string &absolute,
                                           const std::string &directory, std::string &last)
    {
      std::vector<std::string> files;
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
      return files;
    }
    /// The plot a script ended half-way left (NAME.png.partial): the
    /// directory is a run's staging one or a study's, whose .partial files
    /// are the program's own.
    void remove_half_drawn(const std::string &directory)
    {
      std::error_code                    error;
      std::vector<std::filesystem::path> half;
      for (const auto &entry : std::filesystem::directory_iterator(directory, error))
        {
          const std::string name = entry.path().filename().string();
          if (entry.is_regular_file() && name.size() > 12 && name.compare(name.size() - 12, 12, ".png.partial") == 0)
            half.push_back(entry.path());
        }
      for (const auto &path : half)
        std::filesystem::remove(path, error);
    }
  } // namespace

  namespace
  {
    /// Where plot_script() looks, relative to the program's folder.
    const char *const script_places[] = {"../share/nsm-bar", "scripts"};

    /// The folder of the running program (/proc/self/exe), or "".
    std::filesystem::path program_folder()
    {
      std::error_code error;
      const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
      return error ? std::filesystem::path() : program.parent_path();
    }

    /// Rewrites the log's "wrote ABSOLUTE/NAME" lines as "wrote SHOWN/NAME":
    /// the log names the plots where they are once the run's output is in
    /// place, not in its staging directory.
    void name_final_paths(const std::string &log_path, const std::string &absolute, const std::string &shown)
    {
      std::ifstream      in(log_path);
      std::ostringstream text;
      for (std::string line; std::getline(in, line);)
        {
          if (line.rfind("wrote " + absolute + "/", 0) == 0)
            line = "wrote " + shown + line.substr(6 + absolute.size());
          text << line << '\n';
        }
      in.close();
      write_atomically(log_path, [&](std::ostream &out) { out << text.str(); });
    }
  } // namespace

  std::string plot_script()
  {
    const std::filesystem::path folder = program_folder();
    std::error_code             error;
    for (const char *place : script_places)
      {
        const std::filesystem::path script = folder / place / "plot_results.py";
        if (!folder.empty() && std::filesystem::is_regular_file(script, error))
          return std::filesystem::weakly_canonical(script, error).string();
      }
    return "";
  }

  PlotResult make_plots(const ContactParameters &contact, const std::string &directory, const std::string &caption,
                        const std::string &shown_as)
  {
    const std::string script = plot_script();
    if (script.empty())
      {
        PlotResult missing;
        missing.failure = "no plotting script: plot_results.py is neither in " +
                          (program_folder() / script_places[0]).string() + " nor in " +
                          (program_folder() / script_places[1]).string() +
                          " (cmake --install build --prefix DIR installs the program with its scripts)";
        return missing;
      }
    std::ostringstream gap;
    gap.precision(17);
    gap << contact.gap;
    const std::string log_path = directory + "/plots.log";
    std::error_code   error;
    std::filesystem::remove(log_path, error);
    // The directory as an absolute path, after "--": a name that starts with
    // '-' is never read as an option.
    const std::string absolute = std::filesystem::absolute(directory, error).string();
    const ProgramEnd  end      = run_program(
      {NSM_PYTHON, script, "--gap", gap.str(), "--wall", wall_name(contact.wall),
       "--caption=" + printable(caption), "--", absolute},
      log_path);
    PlotResult  result;
    std::string last;
    // The plots the script finished are whole (it renames each into place):
    // they are kept, with the log, whether or not it went on to the end.
    if (end != ProgramEnd::not_started)
      {
        result.files = plots_written(log_path, absolute, directory, last);
        result.files.push_back(log_path);
        if (!shown_as.empty())
          name_final_paths(log_path, absolute, std::filesystem::absolute(shown_as, error).string());
      }
    if (end == ProgramEnd::succeeded && last != done_line)
      result.failure = "the plotting script ended without drawing every plot (its last line: " +
                       (last.empty() ? std::string("none") : last) + ")";
    else if (end == ProgramEnd::stopped)
      {
        result.stopped_by = stop_signal();
        result.failure    = std::string("stopped by ") + stop_signal_name(result.stopped_by);
      }
    else if (end == ProgramEnd::failed)
      result.failure = "the plotting script failed: " + (last.empty() ? std::string("no message") : last);
    else if (end == ProgramEnd::not_started)
      result.failure = "the plotting script " + std::string(NSM_PYTHON) + " could not be started";
    if (!result.failure.empty())
      remove_half_drawn(directory);
    return result;
  }
} // namespace nsm
