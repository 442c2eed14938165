// The output directory is replaced whole or not at all, and never removes a
// file it did not write, even one that appears while the run works.
#include <nsm/base/csv.h>
#include <nsm/base/errors.h>
#include <nsm/output/output_directory.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

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
