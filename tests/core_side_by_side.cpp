// detail::side_by_side (libgsp/src, internal): the solver's preparation runs pairs of steps
// with it, so both must run, both must be done when it returns, and a failure on either side
// must reach the caller (once the other side has finished: nothing is left running).
#include "side_by_side.hpp"   // internal (libgsp/src)

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>

namespace {

using gsp::detail::side_by_side;

TEST(CoreSideBySide, BothRunOnTwoThreadsAndAreDoneOnReturn) {
  std::thread::id beside_id, here_id;
  int a = 0, b = 0;
  side_by_side([&] { beside_id = std::this_thread::get_id(), a = 1; },
               [&] { here_id = std::this_thread::get_id(), b = 2; });
  EXPECT_EQ(a, 1);
  EXPECT_EQ(b, 2);
  EXPECT_EQ(here_id, std::this_thread::get_id());
  EXPECT_NE(beside_id, here_id);
}

TEST(CoreSideBySide, AFailureBesideReachesTheCaller) {
  bool here_done = false;
  EXPECT_THROW(side_by_side([] { throw std::runtime_error("beside"); }, [&] { here_done = true; }),
               std::runtime_error);
  EXPECT_TRUE(here_done);
}

TEST(CoreSideBySide, AFailureHereWaitsForTheOtherSide) {
  std::atomic<bool> beside_done{false};
  try {
    side_by_side(
        [&] {
          std::this_thread::sleep_for(std::chrono::milliseconds(50));
          beside_done = true;
        },
        [] { throw std::logic_error("here"); });
    FAIL() << "no exception";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "here");
  }
  EXPECT_TRUE(beside_done);   // joined before the exception left
}

}  // namespace
