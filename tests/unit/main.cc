// The unit tests' main: one thread, as every nsm-bar run (use_one_thread),
// so that what the tests compute is what the program computes.
#include <nsm/base/threads.h>

#include <gtest/gtest.h>

int main(int argc, char **argv)
{
  nsm::use_one_thread();
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
