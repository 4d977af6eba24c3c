// A dynamic step allocates nothing once its solves have been sized (issue 27: the moving body's
// step is paid thousands of times per run): every vector, program, report and message of the
// step's contact solve, its certificate and the committed memory reuse the storage of the step
// before. Counted here as calls of the replaceable global operator new (every std::vector and
// std::string allocation goes through it) between two accepted steps of
//  - a sphere rolling freely (kappa != 0, the transient model, the convected memory), after the
//    start-up transient (DynamicFreeRolling: the tangential contact mode has decayed by step 300
//    on 16^2);
//  - the paper's cylinder in 2-D under a growing driving moment (the steady model: Newton on the
//    steady equations and a fresh steady sensitivity in most steps), steps 151-200.
// Not run under the sanitizers, whose runtimes own operator new.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>
#include <vector>

#include "case_model.hpp"
#include "cli_runner.hpp"
#include "dynamic_case_support.hpp"
#include "dynamic_simulation.hpp"

#if !DYNCONTACT_SANITIZED
namespace {
std::atomic<long long> operator_new_calls{0};

void* counted(std::size_t size) {
  operator_new_calls.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}

void* counted_aligned(std::size_t size, std::align_val_t align) {
  operator_new_calls.fetch_add(1, std::memory_order_relaxed);
  const std::size_t a = static_cast<std::size_t>(align);
  if (void* p = std::aligned_alloc(a, (size + a - 1) / a * a)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t size) { return counted(size); }
void* operator new[](std::size_t size) { return counted(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return counted(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return counted(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new(std::size_t size, std::align_val_t align) { return counted_aligned(size, align); }
void* operator new[](std::size_t size, std::align_val_t align) { return counted_aligned(size, align); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
#endif

namespace dc::dynamics {
namespace {

#if !DYNCONTACT_SANITIZED
/// Runs `c` and returns the operator-new calls between each accepted step and the one before.
std::vector<long long> allocations_per_step(const Case& c, DynamicResult& result) {
  DynamicSimulation sim(c);
  std::vector<long long> per_step;
  per_step.reserve(1000);
  long long last = operator_new_calls.load();
  result = sim.run([&](const DynamicSample&) {
    const long long now = operator_new_calls.load();
    per_step.push_back(now - last);
    last = operator_new_calls.load();
  });
  return per_step;
}

long long sum_from(const std::vector<long long>& per_step, std::size_t first) {
  long long sum = 0;
  for (std::size_t k = first; k < per_step.size(); ++k) sum += per_step[k];
  return sum;
}
#endif

TEST(DynamicAllocations, ASteadyRollingStepAllocatesNothing) {
#if DYNCONTACT_SANITIZED
  GTEST_SKIP() << "the sanitizers' runtimes own operator new";
#else
  const Case c = build_case(dc::test::free_rolling_bowling_ball(16, 0.04));
  ASSERT_NE(c.materials.kappa(), 0.0);
  DynamicResult r;
  const std::vector<long long> per_step = allocations_per_step(c, r);
  ASSERT_TRUE(r.completed) << r.status;
  ASSERT_EQ(per_step.size(), 400u);
  EXPECT_EQ(sum_from(per_step, 300), 0) << "allocations in steps 301-400; step 301 alone: " << per_step[300]
                                        << ", step 1: " << per_step[0];
#endif
}

TEST(DynamicAllocations, ASteadyModelStepAllocatesNothing) {
#if DYNCONTACT_SANITIZED
  GTEST_SKIP() << "the sanitizers' runtimes own operator new";
#else
  nlohmann::json doc = dc::test::example_json("cylinder-dynamic-2d");
  doc["time"]["t_end"] = 200 * doc["time"]["dt"].get<double>();
  DynamicResult r;
  const std::vector<long long> per_step = allocations_per_step(build_case(doc), r);
  ASSERT_TRUE(r.completed) << r.status;
  ASSERT_EQ(per_step.size(), 200u);
  ASSERT_GT(r.sensitivities, 50) << "most steps take a fresh steady sensitivity";
  EXPECT_EQ(sum_from(per_step, 150), 0) << "allocations in steps 151-200; step 151 alone: " << per_step[150];
#endif
}

}  // namespace
}  // namespace dc::dynamics
