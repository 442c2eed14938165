// The output directory is replaced whole or not at all, and never removes a
// file it did not write, even one that appears while the run works.
#include <nsm/base/csv.h>
#include <nsm/base/errors.h>
#include <nsm/output/output_directory.h>

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace
{
  namespace fs = std::filesystem;

  std::string text_of(const fs::path &path)
  {
    std::ifstream      in(path);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  /// A fresh scratch directory of the test's own.
  fs::path scratch(const std::string &name)
  {
    const fs::path path = fs::temp_directory_path() / ("nsm-output-directory-" + name);
    fs::remove_all(path);
    fs::create_directories(path);
    return path;
  }

  /// One complete run's output in `target`: a file and the manifest.
  void write_run(const std::string &target)
  {
    nsm::OutputDirectory output(target);
    const std::string    file = nsm::write_atomically(output.staging() + "/a.csv", [](std::ostream &out) {
      out << "x\n1\n";
    });
    output.commit({file});
  }
} // namespace

TEST(OutputDirectory, AnEarlierOutputIsReplacedWhole)
{
  const std::string target = (scratch("earlier") / "out").string();
  write_run(target);
  write_run(target);
  EXPECT_EQ(text_of(target + "/a.csv"), "x\n1\n");
  EXPECT_EQ(text_of(target + "/nsm-bar.manifest"), "a.csv\n");
}

TEST(OutputDirectory, AUsersFileBesideADirectoryNamedLikeTheManifestIsKept)
{
  const fs::path target = scratch("thesis") / "mine";
  fs::create_directories(target / "nsm-bar.manifest");
  std::ofstream(target / "thesis.tex") << "my thesis\n";
  EXPECT_THROW(nsm::OutputDirectory output(target.string()), nsm::InputError);
  EXPECT_EQ(text_of(target / "thesis.tex"), "my thesis\n");
}

TEST(OutputDirectory, AFileThatAppearsDuringTheRunIsKeptAndTheRunFails)
{
  // Another program (a study, which writes in place) writes into the
  // directory after this run has checked it.
  const std::string target = (scratch("during") / "out").string();
  nsm::OutputDirectory output(target);
  const std::string    file = nsm::write_atomically(output.staging() + "/a.csv", [](std::ostream &out) {
    out << "x\n1\n";
  });
  fs::create_directories(target);
  std::ofstream(target + "/study.csv") << "rows of another run\n";
  EXPECT_THROW(output.commit({file}), nsm::OutputError);
  EXPECT_EQ(text_of(target + "/study.csv"), "rows of another run\n");
  EXPECT_FALSE(fs::exists(target + "/a.csv"));
}

namespace
{
  /// An earlier run's output with a folder of two VTK snapshots, listed as
  /// field_write_snapshots does ("FOLDER/ (N snapshots)").
  void write_run_with_snapshots(const std::string &target)
  {
    nsm::OutputDirectory output(target);
    const std::string    folder = output.staging() + "/field_0_snapshots";
    fs::create_directories(folder);
    for (const char *name : {"snapshot_0000.vtu", "snapshot_0001.vtu"})
      std::ofstream(folder + "/" + name) << "<VTKFile/>\n";
    const std::string file = nsm::write_atomically(output.staging() + "/a.csv", [](std::ostream &out) {
      out << "x\n1\n";
    });
    output.commit({file, folder + "/ (2 snapshots)"});
  }

  /// Constructing an OutputDirectory on `target` is refused (InputError)
  /// naming `file`.
  void expect_refused_naming(const std::string &target, const std::string &file)
  {
    try
      {
        nsm::OutputDirectory output(target);
        ADD_FAILURE() << "a directory holding " << file << " was taken";
      }
    catch (const nsm::InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
      }
  }

  /// Whether `path` is locked (flock) by another open file.
  bool locked_elsewhere(const fs::path &path)
  {
    const int fd = open(path.c_str(), O_RDONLY | O_DIRECTORY);
    const bool locked = fd >= 0 && flock(fd, LOCK_EX | LOCK_NB) != 0;
    if (fd >= 0)
      close(fd);
    return locked;
  }
} // namespace

// A user's file in a folder the manifest lists is the user's: the folder's
// files are checked by name, not by type, and the run is refused.
TEST(UsersFilesAreNeverRemoved, AFileInASnapshotFolderRefusesTheNextRun)
{
  const std::string target = (scratch("snapshots") / "out").string();
  write_run_with_snapshots(target);
  {
    nsm::OutputDirectory again(target); // the run's own output is taken
  }
  for (const char *name : {"notes.txt", "snapshot_0002.vtu", ".hidden", "snapshot_0000.vtu.bak"})
    {
      std::ofstream(target + "/field_0_snapshots/" + name) << "mine\n";
      expect_refused_naming(target, name);
      EXPECT_EQ(text_of(target + "/field_0_snapshots/" + name), "mine\n");
      fs::remove(target + "/field_0_snapshots/" + name);
    }
  fs::create_directory(target + "/field_0_snapshots/mine");
  expect_refused_naming(target, "mine");
  EXPECT_TRUE(fs::is_directory(target + "/field_0_snapshots/mine"));
}

// A file that appears after the commit's last check goes out with the
// previous output: of that, only the files its manifest lists are removed,
// and the user's goes back into the directory.
TEST(UsersFilesAreNeverRemoved, AFileInThePreviousOutputGoesBackIntoTheDirectory)
{
  const fs::path base = scratch("previous");
  write_run_with_snapshots((base / "previous").string());
  std::ofstream(base / "previous" / "notes.txt") << "mine\n";
  std::ofstream(base / "previous" / "field_0_snapshots" / "notes.txt") << "mine too\n";
  write_run((base / "target").string());
  EXPECT_EQ(nsm::discard_previous_output((base / "previous").string(), (base / "target").string()), "");
  EXPECT_FALSE(fs::exists(base / "previous"));
  EXPECT_EQ(text_of(base / "target" / "notes.txt"), "mine\n");
  EXPECT_EQ(text_of(base / "target" / "field_0_snapshots" / "notes.txt"), "mine too\n");
  EXPECT_FALSE(fs::exists(base / "target" / "field_0_snapshots" / "snapshot_0000.vtu"));
  EXPECT_EQ(text_of(base / "target" / "a.csv"), "x\n1\n");

  // A name the new output took (the old output had no b.csv, the new one
  // has): the user's b.csv stays, in a visible folder that is named.
  fs::remove_all(base / "target");
  write_run((base / "previous").string());
  std::ofstream(base / "previous" / "b.csv") << "mine\n";
  {
    nsm::OutputDirectory output((base / "target").string());
    std::vector<std::string> files;
    for (const char *name : {"/a.csv", "/b.csv"})
      files.push_back(nsm::write_atomically(output.staging() + name, [](std::ostream &out) { out << "new\n"; }));
    output.commit(files);
  }
  const std::string kept = nsm::discard_previous_output((base / "previous").string(), (base / "target").string());
  ASSERT_NE(kept, "");
  EXPECT_EQ(text_of(fs::path(kept) / "b.csv"), "mine\n");
  EXPECT_FALSE(fs::exists(fs::path(kept) / "a.csv"));
  EXPECT_EQ(text_of(base / "target" / "b.csv"), "new\n");
  EXPECT_EQ(fs::path(kept).filename().string().rfind(".", 0), std::string::npos) << "a hidden name: " << kept;
}

// An edited manifest names nothing outside the directory: a line with a
// folder part, "..", or an absolute path removes nothing.
TEST(UsersFilesAreNeverRemoved, AManifestLineOutsideTheDirectoryRemovesNothing)
{
  const fs::path base = scratch("edited");
  write_run((base / "previous").string());
  fs::create_directories(base / "victim");
  for (const char *name : {"snapshot_0000.vtu", "snapshot_0001.vtu", "data.csv"})
    std::ofstream(base / "victim" / name) << "mine\n";
  std::ofstream(base / "previous" / "nsm-bar.manifest", std::ios::app)
    << "../victim/ (2 snapshots)\n" << (base / "victim").string() << "/ (2 snapshots)\n../victim/data.csv\n"
    << (base / "victim" / "data.csv").string() << "\n..\n";
  write_run((base / "target").string());
  nsm::discard_previous_output((base / "previous").string(), (base / "target").string());
  for (const char *name : {"snapshot_0000.vtu", "snapshot_0001.vtu", "data.csv"})
    EXPECT_EQ(text_of(base / "victim" / name), "mine\n") << name;
}

// The race itself: a user's file created in the directory at any moment
// while runs replace it survives every time (before, 14 of 180 went out with
// the previous output).
TEST(UsersFilesAreNeverRemoved, AFileCreatedDuringTheSwapSurvives)
{
  const std::string target = (scratch("race") / "out").string();
  std::mt19937      random(20261127);
  for (int trial = 0; trial < 200; ++trial)
    {
      fs::remove_all(target);
      write_run(target);
      const std::string file  = target + "/user-" + std::to_string(trial) + ".txt";
      const int         delay = std::uniform_int_distribution<int>(0, 400)(random);
      std::thread       user([&] {
        std::this_thread::sleep_for(std::chrono::microseconds(delay));
        std::ofstream(file) << "mine\n";
      });
      try
        {
          write_run(target);
        }
      catch (const std::exception &)
        {
          // Refused or failed because the file is there: as it should.
        }
      user.join();
      ASSERT_TRUE(fs::exists(file)) << "trial " << trial << " (delay " << delay << " us) removed the user's file";
      EXPECT_EQ(text_of(file), "mine\n");
    }
}

// Staging folders of dead runs are removed, a live run's never, whichever
// PID namespace it runs in: the lock tells, not the process number.
TEST(OutputDirectory, ALiveRunsStagingIsKeptWhateverItsProcessNumber)
{
  const fs::path base = scratch("namespaces");
  {
    nsm::OutputDirectory live((base / "out").string());
    const fs::path       staging = live.staging();
    EXPECT_TRUE(locked_elsewhere(staging));
    // A second run into the same directory (here, or in another container
    // whose process numbers mean nothing here) leaves it alone.
    nsm::OutputDirectory second((base / "out").string());
    EXPECT_TRUE(fs::is_directory(staging));
    EXPECT_NE(second.staging(), live.staging());
  }
  // A dead run's, whatever its number (here one of this live process).
  nsm::OutputDirectory probe((base / "out").string());
  const std::string prefix = fs::path(probe.staging()).filename().string().substr(0, 26);
  const fs::path dead = base / (prefix + "run-" + std::to_string(getpid()) + "-0123456789abcdef");
  fs::create_directory(dead);
  // A folder of the user's that only starts like a staging name is not one.
  const fs::path mine = base / (prefix + "mine");
  fs::create_directory(mine);
  std::ofstream(mine / "notes.txt") << "mine\n";
  nsm::OutputDirectory next((base / "out").string());
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::is_directory(probe.staging()));
  EXPECT_EQ(text_of(mine / "notes.txt"), "mine\n");
}

// A run killed in the fallback swap (no RENAME_EXCHANGE) between its renames
// leaves the previous output aside: the next run puts it back.
TEST(OutputDirectory, APreviousOutputLeftAsideIsPutBack)
{
  const fs::path base = scratch("aside");
  write_run((base / "out").string());
  std::string prefix;
  {
    nsm::OutputDirectory probe((base / "out").string());
    prefix = fs::path(probe.staging()).filename().string().substr(0, 26);
  }
  fs::rename(base / "out", base / (prefix + "aside-1-0123456789abcdef"));
  nsm::OutputDirectory next((base / "out").string());
  EXPECT_EQ(text_of(base / "out" / "a.csv"), "x\n1\n");
  EXPECT_FALSE(fs::exists(base / (prefix + "aside-1-0123456789abcdef")));
}

// A failed run removes the parent folders it made, and only those; a name
// no file system takes is refused before anything is made.
TEST(OutputDirectory, AFailedRunLeavesNoFolderItMade)
{
  const fs::path base = scratch("parents");
  fs::create_directories(base / "kept");
  {
    nsm::OutputDirectory output((base / "kept" / "new" / "deeper" / "out").string());
    EXPECT_TRUE(fs::is_directory(base / "kept" / "new" / "deeper"));
  }
  EXPECT_FALSE(fs::exists(base / "kept" / "new"));
  EXPECT_TRUE(fs::is_directory(base / "kept"));
  EXPECT_THROW(nsm::OutputDirectory((base / "made" / std::string(256, 'a')).string()), nsm::InputError);
  EXPECT_FALSE(fs::exists(base / "made"));
  EXPECT_NO_THROW(nsm::OutputDirectory((base / "made" / std::string(255, 'a')).string()));
  EXPECT_FALSE(fs::exists(base / "made"));
}

// Two runs into one folder at once: the second to finish finds the first's
// output swapped in since it began (another inode), keeps it and fails.
TEST(OutputDirectory, AnOutputAnotherRunSwappedInMeanwhileIsKept)
{
  for (const bool existed : {false, true})
    {
      const std::string target = (scratch(existed ? "overlap-existed" : "overlap-new") / "out").string();
      if (existed)
        write_run(target);
      nsm::OutputDirectory slow(target);
      const std::string    mine = nsm::write_atomically(slow.staging() + "/b.csv", [](std::ostream &out) {
        out << "slow\n";
      });
      write_run(target); // the other run, begun and finished meanwhile
      EXPECT_THROW(slow.commit({mine}), nsm::OutputError);
      EXPECT_EQ(text_of(target + "/a.csv"), "x\n1\n");
      EXPECT_FALSE(fs::exists(target + "/b.csv"));
    }
}

// A default folder records its scene file; another scene file with the same
// default is refused it, the same one replaces its own.
TEST(OutputDirectory, ADefaultFolderBelongsToTheSceneFileThatMadeIt)
{
  const std::string target = (scratch("default-owner") / "x").string();
  {
    nsm::OutputDirectory output(target, "/scenes/a/x.prm");
    output.commit({nsm::write_atomically(output.staging() + "/a.csv", [](std::ostream &out) { out << "a\n"; })});
  }
  EXPECT_NE(text_of(target + "/nsm-bar.manifest").find("/ default folder of /scenes/a/x.prm\n"), std::string::npos);
  EXPECT_THROW(nsm::OutputDirectory other(target, "/scenes/b/x.prm"), nsm::InputError);
  EXPECT_NO_THROW(nsm::OutputDirectory same(target, "/scenes/a/x.prm"));
  // An explicit Output/Directory may replace it (the user named the folder).
  EXPECT_NO_THROW(nsm::OutputDirectory named(target));
  // A default folder holding an output made under an explicit Directory is refused.
  const std::string explicit_target = (scratch("default-over-explicit") / "x").string();
  write_run(explicit_target);
  EXPECT_THROW(nsm::OutputDirectory by_default(explicit_target, "/scenes/a/x.prm"), nsm::InputError);
  EXPECT_EQ(text_of(explicit_target + "/a.csv"), "x\n1\n");
}
