// The progress line of long commands (apps/runs/progress.cpp): the count of finished points, steps or
// simulated time with the time left from the finished share, and for one solve the time left
// from the rate at which its residual falls towards the residual it stops at.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "progress.hpp"

namespace {

using dc::ProgressInfo;
using dc::runs::Progress;

/// The seconds of "about N s left" in `line`, or -1 when the line has none.
double seconds_left(const std::string& line) {
  const auto at = line.find("about ");
  if (at == std::string::npos || line.find(" s left", at) == std::string::npos) return -1.0;
  return std::atof(line.c_str() + at + 6);
}

TEST(Progress, CountedPointsShowTheTimeLeftFromTheFinishedShare) {
  Progress p("table of 10 points", false);
  p.count(0, 10);
  EXPECT_EQ(p.line(2.0), "table of 10 points: 2.0 s, 0 of 10 points done");
  p.count(4, 10, "runs");
  EXPECT_EQ(p.line(8.0), "table of 10 points: 8.0 s, 4 of 10 runs done, about 12 s left");
}

TEST(Progress, SimulatedTimeShowsTheTimeLeft) {
  Progress p("dynamic", false);
  p.time(0.025, 0.1);
  EXPECT_EQ(p.line(3.0), "dynamic: 3.0 s, t = 0.025 of 0.1 s, about 9 s left");
}

TEST(Progress, AHistoryCountsItsStepsAndShowsTheSolveUnderWay) {
  Progress p("solving", false);
  auto report = p.callback();
  report(ProgressInfo{7, 0.0, 1e-3, 1e-9, 2, 5});
  EXPECT_EQ(p.line(4.0), "solving: 4.0 s, 2 of 5 steps done, iteration 7, residual 1.00e-03, about 6 s left");
}

TEST(Progress, OneSolveEstimatesTheTimeLeftFromItsConvergenceRate) {
  // The residual falls a decade per ~0.2 s; three decades remain to the target: about 0.6 s.
  Progress p("solving", false);
  auto report = p.callback();
  report(ProgressInfo{1, 0.0, 1e-1, 1e-5});
  EXPECT_LT(seconds_left(p.line(1.0)), 0.0) << "no rate from one residual";
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  report(ProgressInfo{2, 0.0, 1e-2, 1e-5});
  const std::string line = p.line(1.2);
  EXPECT_NE(line.find("iteration 2, residual 1.00e-02"), std::string::npos) << line;
  const double left = seconds_left(line);
  EXPECT_GE(left, 0.0) << line;
  EXPECT_LE(left, 3.0) << line;  // 0.6 s at the rate seen (the printed value is rounded)
  // A new solve (the iteration count starts again) forgets the old rate.
  report(ProgressInfo{0, 0.0, 5e-1, 1e-5});
  EXPECT_LT(seconds_left(p.line(1.3)), 0.0) << p.line(1.3);
  // No target reported: no estimate.
  report(ProgressInfo{1, 0.0, 1e-1, 0.0});
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  report(ProgressInfo{2, 0.0, 1e-2, 0.0});
  EXPECT_LT(seconds_left(p.line(1.4)), 0.0) << p.line(1.4);
}

}  // namespace
