// The work spreader of `table` and sweeps (apps/table/table_ranks.cpp, here without MPI): every
// unit runs once, results come back in unit order whichever thread finished first, a unit that
// throws becomes {"error": message} with the others kept, progress is reported up to the total,
// and a launch by mpirun of a build without MPI is an input error rather than N copies of the job.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "errors.hpp"
#include "interrupt.hpp"
#include "table_ranks.hpp"

namespace {

using nlohmann::json;

/// Sets an environment variable for the scope.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) { ::setenv(name, value, 1); }
  ~ScopedEnv() { ::unsetenv(name_); }

 private:
  const char* name_;
};

class TableRanks : public ::testing::TestWithParam<const char*> {};

TEST_P(TableRanks, AFailingUnitIsReportedAndTheOthersKeptInUnitOrder) {
  const ScopedEnv threads("DYNCONTACT_THREADS", GetParam());
  constexpr std::size_t kUnits = 23;
  std::vector<std::atomic<int>> runs(kUnits);
  // Uneven units (the later ones quicker), two that throw (a std::exception and something else).
  const auto work = [&](std::size_t u) -> json {
    ++runs[u];
    std::this_thread::sleep_for(std::chrono::milliseconds(kUnits - u));
    if (u == 5) throw std::runtime_error("unit five cannot be solved");
    if (u == 17) throw 17;
    return {{"unit", u}, {"square", static_cast<double>(u * u) / 3.0}};
  };
  std::vector<std::size_t> progress;
  const auto done = [&](std::size_t finished, std::size_t units) {
    EXPECT_EQ(units, kUnits);
    progress.push_back(finished);
  };
  const std::vector<json> results = dc::table::run_distributed(kUnits, work, done);

  ASSERT_EQ(results.size(), kUnits);
  for (std::size_t u = 0; u < kUnits; ++u) {
    SCOPED_TRACE(u);
    EXPECT_EQ(runs[u].load(), 1);
    if (u == 5) {
      EXPECT_EQ(results[u], json({{"error", "unit five cannot be solved"}}));
    } else if (u == 17) {
      EXPECT_EQ(results[u], json({{"error", "unknown exception"}}));
    } else {
      EXPECT_EQ(results[u]["unit"], u);
      // The value passed through its JSON text unchanged (as a remote rank's would).
      EXPECT_EQ(results[u]["square"].get<double>(), static_cast<double>(u * u) / 3.0);
    }
  }
  // Progress starts at 0, never goes back and ends at the total.
  ASSERT_FALSE(progress.empty());
  EXPECT_EQ(progress.front(), 0u);
  EXPECT_EQ(progress.back(), kUnits);
  for (std::size_t k = 1; k < progress.size(); ++k) EXPECT_GE(progress[k], progress[k - 1]);
}

/// The test's name: threads_N.
std::string threads_name(const ::testing::TestParamInfo<const char*>& p) { return std::string("threads_") + p.param; }

INSTANTIATE_TEST_SUITE_P(Threads, TableRanks, ::testing::Values("1", "2", "4"), threads_name);

TEST(TableRanksInterrupt, NoUnitStartsAfterAnInterrupt) {
  // One worker: unit 3 asks for the interrupt (as a signal would) and finishes; the units after
  // it never start and have no result, those before keep theirs.
  const ScopedEnv threads("DYNCONTACT_THREADS", "1");
  std::vector<int> started;
  const auto work = [&](std::size_t u) -> json {
    started.push_back(static_cast<int>(u));
    if (u == 3) dc::request_interrupt(0);
    return {{"unit", u}};
  };
  const std::vector<json> results = dc::table::run_distributed(10, work, {});
  dc::clear_interrupt();
  EXPECT_EQ(started, (std::vector<int>{0, 1, 2, 3}));
  ASSERT_EQ(results.size(), 10u);
  for (std::size_t u = 0; u < 10; ++u) {
    if (u <= 3) {
      EXPECT_EQ(results[u]["unit"], u);
    } else {
      EXPECT_TRUE(results[u].is_null()) << u;
    }
  }
}

TEST(TableRanksInterrupt, AnInterruptedUnitHasNoResult) {
  // A unit that unwinds with dc::Interrupted (a solver noticing the flag) is not an error.
  const ScopedEnv threads("DYNCONTACT_THREADS", "2");
  const auto work = [&](std::size_t u) -> json {
    if (u == 1) {
      dc::request_interrupt(0);
      dc::throw_if_interrupted();
    }
    return {{"unit", u}};
  };
  const std::vector<json> results = dc::table::run_distributed(6, work, {});
  dc::clear_interrupt();
  ASSERT_EQ(results.size(), 6u);
  EXPECT_TRUE(results[1].is_null());
  for (const json& r : results) EXPECT_FALSE(r.contains("error")) << r.dump();
}

TEST(TableRanksLaunch, NoUnitsIsAnEmptyResult) {
  bool reported = false;
  const auto results = dc::table::run_distributed(0, [](std::size_t) { return json(); },
                                                [&](std::size_t finished, std::size_t units) {
                                                  EXPECT_EQ(finished, 0u);
                                                  EXPECT_EQ(units, 0u);
                                                  reported = true;
                                                });
  EXPECT_TRUE(results.empty());
  EXPECT_TRUE(reported);
}

TEST(TableRanksLaunch, TheRankComesFromTheLauncher) {
  EXPECT_TRUE(dc::table::launch_rank().root());
  const ScopedEnv rank("OMPI_COMM_WORLD_RANK", "3"), size("OMPI_COMM_WORLD_SIZE", "4");
  const dc::table::LaunchRank r = dc::table::launch_rank();
  EXPECT_EQ(r.rank, 3);
  EXPECT_EQ(r.size, 4);
  EXPECT_FALSE(r.root());
}

TEST(TableRanksLaunch, MpirunOfABuildWithoutMpiIsAnInputError) {
  ASSERT_FALSE(dc::table::built_with_mpi());  // no MPI transport: the program alone installs one
  const ScopedEnv rank("OMPI_COMM_WORLD_RANK", "0"), size("OMPI_COMM_WORLD_SIZE", "2");
  bool ran = false;
  const auto work = [&](std::size_t) {
    ran = true;
    return json();
  };
  try {
    dc::table::run_distributed(4, work, {});
    FAIL() << "expected an input error";
  } catch (const dc::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("without MPI"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(ran);
}

}  // namespace
