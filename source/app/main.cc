// nsm-bar SCENE.prm [--set ...] [--output DIR] [--resume] [--verbose]: argument handling
// only; the work is in run_scene(), or in run_study() for a scene that is a
// study.
#include <nsm/app/exit_codes.h>
#include <nsm/app/pipeline.h>
#include <nsm/app/run_record.h>
#include <nsm/continuation/checkpoint.h>
#include <nsm/scene/scene.h>
#include <nsm/base/interruption.h>
#include <nsm/base/threads.h>
#include <nsm/scene/parameter_listing.h>
#include <nsm/scene/scene_file.h>
#include <nsm/base/text.h>
#include <nsm/study/study.h>
#include <nsm/base/assertions.h>
#include <nsm/base/errors.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <initializer_list>
#include <cstdlib>
#include <iostream>
#include <new>
#include <optional>
#include <string>
#include <vector>

namespace
{
  /// Whether an MPI launcher started this process (Open MPI's mpirun, or a
  /// PMI or PMIx one).
  bool started_by_mpirun()
  {
    for (const char *variable : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE", "PMI_RANK"})
      if (std::getenv(variable) != nullptr)
        return true;
    return false;
  }

  /// The value of the first of these environment variables that is set, as
  /// a whole number; -1 if none is.
  long launcher_number(const std::initializer_list<const char *> variables)
  {
    for (const char *variable : variables)
      if (const char *value = std::getenv(variable))
        return std::strtol(value, nullptr, 10);
    return -1;
  }

  /// This process's rank and the number of ranks as the MPI launcher set
  /// them (known before MPI_Init, which a scene does not call): 0 and 1
  /// without a launcher.
  long launcher_rank() { return std::max(0L, launcher_number({"OMPI_COMM_WORLD_RANK", "PMIX_RANK", "PMI_RANK"})); }
  long launcher_size() { return std::max(1L, launcher_number({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})); }

  /// The command line's overrides, for the summary's first line.
  std::string overrides_note()
  {
    std::string note;
    for (const nsm::ParameterOverride &o : nsm::parameter_overrides())
      note += (note.empty() ? " with " : ", ") + o.path + " = " + nsm::printable(o.value);
    return note;
  }

  /// 0, or 5 with its line on stderr if the plots were not drawn (the other
  /// files are written).
  int plot_failure_code(const nsm::RunReport &report)
  {
    if (report.plot_failure.empty())
      return 0;
    nsm::print_error("output error: ", "the plots were not drawn, every other file is written: " + report.plot_failure);
    return nsm::exit_codes::output;
  }

  /// Runs the scene (a study over the MPI ranks, if any); returns the exit
  /// code, the error printed.
  int run(int &argc, char **&argv, const std::string &path, const bool verbose, const bool resume,
          std::optional<dealii::Utilities::MPI::MPI_InitFinalize> &mpi)
  {
    const std::string command_line = nsm::quoted_command_line(std::vector<std::string>(argv, argv + argc));
    try
      {
        const nsm::StudyScene file = nsm::StudyScene::from_file(path);
        if (!file.study.enabled())
          {
            // A scene is one run into one directory: several ranks would
            // run it several times into the same folder.
            if (launcher_size() > 1)
              throw nsm::InputError("command line: a scene runs on one process, and mpirun started " +
                                    std::to_string(launcher_size()) +
                                    ": run it without mpirun (a study spreads its rows over the ranks)");
            std::cout << "nsm-bar: scene " << path << overrides_note() << '\n';
            // SIGINT or SIGTERM stops the continuation at its next point,
            // and the run writes what it has (interruption.h).
            nsm::catch_stop_signals();
            nsm::stop_at_points(true);
            // Answered at once: a verification point can take a while.
            nsm::acknowledge_stops("nsm-bar: stop asked: the run stops at its next point, or ends the plots it "
                                   "draws, and writes what it computed\n",
                                   nullptr, false);
            const nsm::RunReport report = nsm::run_scene(file.scene, resume, command_line);
            nsm::print_report(report, std::cout, verbose);
            if (report.stopped_by != 0)
              {
                std::cerr << "nsm-bar: stopped by " << nsm::stop_signal_name(report.stopped_by)
                          << "; the output holds what was computed before"
                          << (report.resumable ? " (nsm-bar " + nsm::printable(path) + " --resume goes on from it, with the same --set and --output)" :
                                                 " (no backbone was traced to go on from, so it leaves no " +
                                                   std::string(nsm::checkpoint_file) + ": run the scene again to finish it)")
                          << '\n';
                return nsm::stop_exit_code(report.stopped_by);
              }
            if (!report.failure.empty())
              {
                nsm::print_error("numerical failure: ", report.failure);
                return nsm::exit_codes::numerical;
              }
            return plot_failure_code(report);
          }
        if (resume)
          throw nsm::InputError("command line: --resume is for a scene; a study resumes by itself (its rows "
                                "done are kept in study.csv)");
        // MPI only where mpirun started the process: a serial study needs
        // none, and MPI's own start-up fails under tight resource limits.
        if (started_by_mpirun())
          mpi.emplace(argc, argv, 1);
        // A study stops at the next row boundary on SIGINT or SIGTERM: the
        // rows written so far are kept, and a rerun resumes (set after
        // MPI_Init, which sets handlers of its own).
        nsm::catch_stop_signals();
        // Answered at once: a row can take minutes. Serially, a second stop
        // ends the current row at its next point (under mpirun the launcher
        // decides how signals reach the ranks).
        if (!mpi || dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) == 1)
          nsm::acknowledge_stops(
            "nsm-bar: stop asked: the study stops after its current row (study.csv keeps the rows done, a rerun "
            "goes on); ask again to stop that row at its next point and leave it out\n",
            "nsm-bar: stop asked again: the current row stops at its next point and is left out\n", true);
        const bool           root   = !mpi || dealii::Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
        nsm::RunReport report = nsm::run_study(path, file);
        if (root)
          {
            // The study's record, as a run's: summary.txt in its folder,
            // written after the summary is printed (a failure to write it
            // leaves the printed summary).
            const std::string summary = file.scene.output.directory + "/summary.txt";
            report.files.push_back(summary);
            std::cout << "nsm-bar: study " << path << overrides_note() << '\n';
            nsm::print_report(report, std::cout);
            nsm::write_summary(summary, command_line, report);
          }
        if (report.stopped_by == 0)
          return root ? plot_failure_code(report) : 0;
        if (root)
          std::cerr << "nsm-bar: stopped by " << nsm::stop_signal_name(report.stopped_by)
                    << "; study.csv holds the rows done, a rerun computes the others\n";
        return nsm::stop_exit_code(report.stopped_by);
      }
    catch (...)
      {
        // Bad input is the same on every rank: rank 0 says it.
        return nsm::report_failure(std::current_exception(), launcher_rank() == 0);
      }
  }

  const char *const usage = "usage: nsm-bar SCENE.prm [--set \"Section/Entry=value\"]... [--output DIR] [--resume] [--verbose]\n"
                            "       nsm-bar DIR --resume [--set ...]\n"
                            "       mpirun --allow-run-as-root -np R nsm-bar STUDY.prm [--set ...]\n"
                            "       nsm-bar --print-parameters[=markdown]\n"
                            "       nsm-bar --help\n";

  /// The command line: one scene and its overrides.
  struct CommandLine
  {
    std::string                         scene;
    bool                                verbose = false;
    bool                                resume  = false;
    std::vector<nsm::ParameterOverride> overrides;
  };

  /// `nsm-bar DIR --resume`: the scene is the run record's DIR/parameters.prm
  /// (every entry as the stopped run read it, its --set values included),
  /// into DIR itself; other --set values may follow it.
  CommandLine resumed_from_record(CommandLine line, const bool output_given)
  {
    std::error_code error;
    if (!line.resume || !std::filesystem::is_directory(line.scene, error))
      return line;
    const std::string directory = line.scene;
    // The run goes on in its own folder; another would hold no checkpoint.
    if (output_given)
      throw nsm::InputError("command line: --output with --resume '" + nsm::printable(directory) +
                            "': the stopped run goes on in its own folder; allowed: nsm-bar " +
                            nsm::printable(directory) + " --resume without --output");
    line.scene                  = directory + "/parameters.prm";
    if (!std::filesystem::is_regular_file(line.scene, error))
      throw nsm::InputError("command line: --resume '" + nsm::printable(directory) +
                            "': it holds no parameters.prm (the record a run writes): give the scene file instead");
    line.overrides.insert(line.overrides.begin(), {"Output/Directory", directory});
    return line;
  }

  /// Parses the arguments after the program name; throws InputError.
  CommandLine parse_command_line(const std::vector<std::string> &arguments)
  {
    CommandLine line;
    bool        output_given = false;
    for (std::size_t i = 0; i < arguments.size(); ++i)
      {
        const std::string &a = arguments[i];
        const auto value = [&](const std::string &option) {
          if (a.size() > option.size() && a.compare(0, option.size() + 1, option + "=") == 0)
            return a.substr(option.size() + 1);
          if (i + 1 == arguments.size())
            throw nsm::InputError("command line: " + option + " needs a value");
          return arguments[++i];
        };
        if (a == "--set" || a.rfind("--set=", 0) == 0)
          line.overrides.push_back(nsm::parse_override(value("--set")));
        else if (a == "--output" || a.rfind("--output=", 0) == 0)
          {
            // An empty value (a shell variable unset) would write the
            // scene's default folder; a second one would override the first.
            const std::string folder = value("--output");
            if (folder.empty())
              throw nsm::InputError("command line: --output has an empty folder name; allowed: a folder path "
                                    "(leave --output out for the scene's Output/Directory)");
            if (output_given)
              throw nsm::InputError("command line: --output given twice; allowed: one output folder");
            output_given = true;
            line.overrides.push_back({"Output/Directory", folder});
          }
        else if (a == "--verbose")
          line.verbose = true;
        else if (a == "--resume")
          line.resume = true;
        else if (a.rfind("--", 0) == 0 && a.size() > 2)
          throw nsm::InputError("command line: unknown option '" + nsm::printable(a) + "' (nsm-bar --help)");
        else if (!line.scene.empty())
          throw nsm::InputError("command line: one scene only, not '" + nsm::printable(line.scene) + "' and '" +
                                nsm::printable(a) + "'");
        else
          line.scene = a;
      }
    if (line.scene.empty())
      throw nsm::InputError("command line: no scene given");
    return resumed_from_record(line, output_given);
  }

} // namespace

int main(int argc, char **argv)
{
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  if (arguments.size() == 1 && (arguments[0] == "--help" || arguments[0] == "-h"))
    {
      std::cout << usage
                << "--set \"Section/Entry=value\"  override a scene entry (repeatable; checked like the file)\n"
                   "--output DIR                  the same as --set \"Output/Directory=DIR\"\n"
                   "--resume                      go on with the continuation of this scene's interrupted run, from\n"
                   "                              the checkpoint it left in Output/Directory (continuation.resume);\n"
                   "                              nsm-bar DIR --resume takes the scene from DIR's record (parameters.prm)\n"
                   "--verbose                     print the continuation's events in the summary too\n"
                   "exit codes: 0 done, 2 bad input, 3 numerical failure, 4 other error, 5 a file could "
                   "not be written whole, 6 a bug in nsm-bar, 130 / 143 stopped by SIGINT / SIGTERM (a run "
                   "writes what it computed, a study keeps its rows done)\n";
      return 0;
    }
  if (arguments.size() == 1 &&
      (arguments[0] == "--print-parameters" || arguments[0] == "--print-parameters=markdown"))
    {
      dealii::ParameterHandler prm;
      nsm::StudyScene::declare(prm);
      if (arguments[0] == "--print-parameters")
        prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
      else
        nsm::print_parameters_markdown(prm, std::cout);
      return 0;
    }
  if (arguments.empty())
    {
      std::cerr << usage;
      return nsm::exit_codes::input;
    }
  CommandLine line;
  try
    {
      line = parse_command_line(arguments);
    }
  catch (...)
    {
      return nsm::report_failure(std::current_exception(), launcher_rank() == 0);
    }
  nsm::set_parameter_overrides(line.overrides);
#ifdef DEBUG
  nsm::throw_on_failed_asserts();
#endif
  // Past a file size limit a write fails (an output error, exit 5) instead of
  // the kernel killing the run half-way.
  std::signal(SIGXFSZ, SIG_IGN);
  nsm::use_one_thread();
  std::optional<dealii::Utilities::MPI::MPI_InitFinalize> mpi;
  const int code = run(argc, argv, line.scene, line.verbose, line.resume, mpi);
  // A rank that failed alone would leave the others waiting in a collective;
  // bad input fails on every rank alike.
  if (code != 0 && code != nsm::exit_codes::input && code < 128 && mpi &&
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    MPI_Abort(MPI_COMM_WORLD, code);
  return code;
}
