// What a failure says and its exit code (app/exit_codes.h), and the Debug
// build's checks of the kernels' preconditions (base/assertions.h): each
// broken precondition is caught where it is made, as a logic error.
#include <nsm/app/exit_codes.h>
#include <nsm/base/assertions.h>
#include <nsm/base/dense_lu.h>
#include <nsm/base/errors.h>
#include <nsm/harmonic_balance/structured_gram.h>
#include <nsm/harmonic_balance/trigonometric.h>
#include <nsm/harmonic_balance/trigonometric_series.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
  /// The exit code of `failure` and the line it printed.
  template <typename Failure>
  std::pair<int, std::string> reported(const Failure &failure)
  {
    testing::internal::CaptureStderr();
    const int code = nsm::report_failure(std::make_exception_ptr(failure));
    return {code, testing::internal::GetCapturedStderr()};
  }
} // namespace

TEST(FailureCodes, EachKindOfFailureHasItsOwnCodeAndLine)
{
  EXPECT_EQ(reported(nsm::InputError("parameter 'X' = 1")).first, nsm::exit_codes::input);
  EXPECT_EQ(reported(nsm::NumericalError("no convergence")).first, nsm::exit_codes::numerical);
  EXPECT_EQ(reported(nsm::OutputError("disk full")).first, nsm::exit_codes::output);
  EXPECT_EQ(reported(std::runtime_error("a library's")).first, nsm::exit_codes::other);
  EXPECT_EQ(reported(dealii::ExcMessage("a library's")).first, nsm::exit_codes::other);
  const auto [code, line] = reported(nsm::LogicError("an invariant"));
  EXPECT_EQ(code, nsm::exit_codes::internal);
  EXPECT_EQ(line.rfind("nsm-bar: internal error (a bug in nsm-bar", 0), 0u) << line;
  EXPECT_NE(line.find("an invariant"), std::string::npos) << line;
  EXPECT_EQ(std::count(line.begin(), line.end(), '\n'), 1) << line;
  // The exceptions of deal.II's Assert family are bugs too.
  EXPECT_EQ(reported(dealii::ExcDimensionMismatch(3, 4)).first, nsm::exit_codes::internal);
  EXPECT_EQ(reported(nsm::ExcPrecondition("set_omega() first")).first, nsm::exit_codes::internal);
  EXPECT_EQ(reported(std::out_of_range("vector::at")).first, nsm::exit_codes::internal);
  EXPECT_EQ(reported(nsm::InputError("x")).second.rfind("nsm-bar: input error: ", 0), 0u);
}

TEST(FailureCodes, BadInputIsSaidOnlyWhereAsked)
{
  testing::internal::CaptureStderr();
  EXPECT_EQ(nsm::report_failure(std::make_exception_ptr(nsm::InputError("x")), false), nsm::exit_codes::input);
  EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

#ifdef DEBUG
TEST(DebugChecks, AKernelGivenTheWrongSizeIsStopped)
{
  const nsm::TrigonometricBasis basis = nsm::harmonic_basis(4, false);
  EXPECT_NO_THROW(nsm::TrigonometricSeries(basis, std::vector<double>(basis.size(), 1.0)));
  EXPECT_THROW(nsm::TrigonometricSeries(basis, std::vector<double>(basis.size() + 1, 1.0)),
               dealii::ExcDimensionMismatch);
  const nsm::StructuredGram gram(basis);
  std::vector<double>       out;
  EXPECT_THROW(gram.multiply(std::vector<double>(basis.size() - 1, 1.0), out), dealii::ExcDimensionMismatch);
}

TEST(DebugChecks, APivotOutsideTheRemainingRowsIsStopped)
{
  // Row k is swapped with a row at or below it: a pivot above k is a bug.
  std::vector<double> lu = {2, 0, 0, 3}, x = {1, 1};
  const std::vector<int> good = {0, 1}, bad = {1, 0};
  EXPECT_NO_THROW(nsm::lu_solve(2, lu.data(), good.data(), x.data()));
  EXPECT_THROW(nsm::lu_solve(2, lu.data(), bad.data(), x.data()), dealii::ExcIndexRangeType<int>);
  EXPECT_THROW(nsm::lu_factor(0, lu.data(), nullptr), dealii::ExcLowerRange);
}
#else
TEST(DebugChecks, AKernelGivenTheWrongSizeIsStopped) { GTEST_SKIP() << "Asserts are compiled only in Debug builds (./test.sh --debug)"; }
#endif
