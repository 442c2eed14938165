// The unit tests' main: one thread, as every nsm-bar run (use_one_thread),
// so that what the tests compute is what the program computes; failed
// Asserts (Debug builds) throw, as in the program.
#include <nsm/base/assertions.h>
#include <nsm/base/threads.h>

#include <gtest/gtest.h>

int main(int argc, char **argv)
{
  nsm::use_one_thread();
  // A failed Assert throws (the Debug build's tests expect its exception).
  nsm::throw_on_failed_asserts();
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
