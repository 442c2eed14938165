// Newton on the HB system at fixed Omega (NOX), and what its solves cost.
#pragma once

#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/scene/harmonic_balance_parameters.h>

#include <memory>
#include <vector>

namespace nsm
{
  /// Wall time and Newton iterations of the solves that converged and of
  /// those that did not (folds and leap attempts), for benchmarks.
  struct NewtonCost
  {
    double        converged_seconds = 0, failed_seconds = 0;
    unsigned long converged_solves = 0, failed_solves = 0;
    unsigned long converged_iterations = 0, failed_iterations = 0;

    NewtonCost &operator+=(const NewtonCost &other)
    {
      converged_seconds += other.converged_seconds;
      failed_seconds += other.failed_seconds;
      converged_solves += other.converged_solves;
      failed_solves += other.failed_solves;
      converged_iterations += other.converged_iterations;
      failed_iterations += other.failed_iterations;
      return *this;
    }

    /// The cost since `earlier`, a copy of this cost taken before.
    NewtonCost since(const NewtonCost &earlier) const
    {
      NewtonCost d = *this;
      d.converged_seconds -= earlier.converged_seconds;
      d.failed_seconds -= earlier.failed_seconds;
      d.converged_solves -= earlier.converged_solves;
      d.failed_solves -= earlier.failed_solves;
      d.converged_iterations -= earlier.converged_iterations;
      d.failed_iterations -= earlier.failed_iterations;
      return d;
    }
  };

  /// Outcome of one Newton solve at fixed Omega (NOX).
  struct NewtonResult
  {
    bool                converged;
    unsigned int        iterations;
    double              residual;
    std::vector<double> x;
    /// Stopped unconverged at Max iterations, rather than stalled or
    /// diverged: more iterations might converge.
    bool at_iteration_limit;
  };

  /// Newton on the HB system at fixed Omega, on NOX's LAPACK group.
  class NewtonSolver
  {
  public:
    NewtonSolver(HarmonicBalance &hb, const HarmonicBalanceParameters &params);
    ~NewtonSolver();
    NewtonResult solve(double omega, const std::vector<double> &guess);

    const NewtonCost &cost() const { return cost_; }

  private:
    NewtonCost cost_;
    struct Impl;
    std::unique_ptr<Impl> impl_;
  };
} // namespace nsm
