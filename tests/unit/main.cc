// The unit tests' main: one thread, as every nsm-bar run (use_one_thread),
// so that what the tests compute is what the program computes; failed
// Asserts (Debug builds) throw, as in the program; a run whose every test was
// skipped exits NSM_UNIT_SKIPPED_EXIT_CODE (tests/CMakeLists.txt). The tests
// write their scenes and logs into a scratch folder of their own, removed when
// every test passed, so a run from the source tree leaves nothing there.
#include <nsm/base/assertions.h>
#include <nsm/base/threads.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <unistd.h>

int main(int argc, char **argv)
{
  nsm::use_one_thread();
  // A failed Assert throws (the Debug build's tests expect its exception).
  nsm::throw_on_failed_asserts();
  ::testing::InitGoogleTest(&argc, argv);
  const std::filesystem::path scratch =
    std::filesystem::temp_directory_path() / ("nsm-unit-tests-" + std::to_string(::getpid()));
  std::filesystem::create_directories(scratch);
  std::filesystem::current_path(scratch);
  const int status = RUN_ALL_TESTS();
  if (status == 0)
    {
      std::filesystem::current_path(scratch.parent_path());
      std::filesystem::remove_all(scratch);
    }
  // Every test that ran was skipped and none failed (DebugChecks in a Release
  // build): CTest shows the run skipped (SKIP_RETURN_CODE,
  // tests/unit_suites.cmake).
  const ::testing::UnitTest &unit = *::testing::UnitTest::GetInstance();
  if (status == 0 && unit.skipped_test_count() > 0 && unit.successful_test_count() == 0)
    return NSM_UNIT_SKIPPED_EXIT_CODE;
  return status;
}
