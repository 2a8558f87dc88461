// How many failures the running test has recorded so far: helpers that check many things
// compare it before and after, to stop early or report a pair as failed, whatever failed
// earlier in the same test.
#pragma once

#include <gtest/gtest.h>

namespace cslice::testkit {

inline int failures_so_far() {
  return ::testing::UnitTest::GetInstance()->current_test_info()->result()->total_part_count();
}

}  // namespace cslice::testkit
