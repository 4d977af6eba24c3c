// The fallback loop's one rule (nlp/certified_solve.hpp), shared by the normal, tangential and
// finite problems: converged beats everything, a point beats none, the smaller certificate wins
// between unconverged points; the report lists the attempts not kept and what was tried.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "certified_solve.hpp"

namespace {

struct Answer {
  dc::SolverReport report;
  int id = 0;
};

Answer attempt(const char* backend, dc::SolveStatus status, double certificate, int id, bool fallback = true) {
  Answer a;
  a.report.backend = backend;
  a.report.status = status;
  a.report.message = std::string(backend) + " said so";
  a.report.certificate.complementarity = certificate;
  a.report.fallback_used = fallback;
  a.id = id;
  return a;
}

}  // namespace

TEST(CertifiedSolve, ConvergedBeatsAPointAndAPointBeatsNone) {
  using dc::SolveStatus;
  const auto conv = attempt("ipopt", SolveStatus::converged, 1e-9, 0).report;
  const auto close = attempt("native", SolveStatus::not_converged, 1e-4, 0).report;
  const auto far = attempt("nlopt", SolveStatus::not_converged, 1e-1, 0).report;
  const auto none = attempt("native", SolveStatus::failed, 0.0, 0).report;
  EXPECT_TRUE(dc::better_result(conv, close));
  EXPECT_TRUE(dc::better_result(conv, none));
  EXPECT_FALSE(dc::better_result(close, conv));
  EXPECT_TRUE(dc::better_result(close, none));
  EXPECT_FALSE(dc::better_result(none, close));
  EXPECT_TRUE(dc::better_result(close, far));
  EXPECT_FALSE(dc::better_result(far, close));
  EXPECT_FALSE(dc::better_result(close, close));  // a tie keeps the earlier result
}

TEST(CertifiedSolve, LedgerKeepsTheBestAndReportsTheOthers) {
  using dc::SolveStatus;
  Answer first;
  first.report.requested = "auto";
  dc::AttemptLedger<Answer> ledger(first);
  EXPECT_TRUE(ledger.record(attempt("native", SolveStatus::not_converged, 1e-2, 1, false), true));
  EXPECT_FALSE(ledger.record(attempt("nlopt", SolveStatus::failed, 0.0, 2), false));
  EXPECT_TRUE(ledger.record(attempt("ipopt", SolveStatus::not_converged, 1e-5, 3), true));
  EXPECT_FALSE(ledger.converged());
  const Answer kept = std::move(ledger).finish();
  EXPECT_EQ(kept.id, 3);
  ASSERT_EQ(kept.report.failed_attempts.size(), 2u);
  EXPECT_EQ(kept.report.failed_attempts[0].backend, "native");
  EXPECT_DOUBLE_EQ(kept.report.failed_attempts[0].certificate, 1e-2);
  EXPECT_EQ(kept.report.failed_attempts[1].backend, "nlopt");
  EXPECT_EQ(kept.report.failed_attempts[1].certificate, std::numeric_limits<double>::infinity());
  EXPECT_EQ(kept.report.message,
            "ipopt said so [tried native: not_converged; nlopt: failed; ipopt: not_converged]");
}

TEST(CertifiedSolve, AFirstConvergedAnswerIsReportedAsItIs) {
  dc::AttemptLedger<Answer> ledger(Answer{});
  ledger.record(attempt("native", dc::SolveStatus::converged, 1e-9, 7, false), true);
  EXPECT_TRUE(ledger.converged());
  const Answer kept = std::move(ledger).finish();
  EXPECT_EQ(kept.id, 7);
  EXPECT_TRUE(kept.report.failed_attempts.empty());
  EXPECT_EQ(kept.report.message, "native said so");
}
