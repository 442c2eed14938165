// The HB system as NOX and LOCA see it, shared by Newton at fixed Omega
// (newton_solver) and the pseudo-arclength stepper (loca_arclength): the
// LOCA::LAPACK interface, Newton's stopping tests and parameters.
#pragma once

#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/scene/harmonic_balance_parameters.h>

#include <LOCA_LAPACK.H>
#include <NOX.H>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <vector>

namespace nsm
{
  /// A system LOCA's dense group solves (continuation/dense_lu_group.h): the
  /// LAPACK interface with dR/dW, and a clock for its linear solves.
  class LocaSystem : public LOCA::LAPACK::Interface
  {
  public:
    /// dR/dW at x.
    virtual bool compute_domega(NOX::LAPACK::Vector &result, const NOX::LAPACK::Vector &x) = 0;
    /// Records the wall time of a Jacobian's LU and its solves.
    virtual void record_linear_solve(double /*seconds*/) {}
  };

  /// The HB system at the Omega LOCA or the Newton driver sets.
  class HbInterface : public LocaSystem
  {
  public:
    HbInterface(HarmonicBalance &hb, std::vector<double> guess)
      : hb_(hb)
      , guess_(guess.size())
    {
      set_guess(guess);
    }

    void set_guess(const std::vector<double> &guess)
    {
      for (unsigned int i = 0; i < guess.size(); ++i)
        guess_(i) = guess[i];
    }

    const NOX::LAPACK::Vector &getInitialGuess() override { return guess_; }

    bool computeF(NOX::LAPACK::Vector &f, const NOX::LAPACK::Vector &x) override
    {
      hb_.set_omega(omega_);
      hb_.evaluate(to_std(x), &scratch_, nullptr, nullptr);
      for (unsigned int i = 0; i < scratch_.size(); ++i)
        f(i) = scratch_[i];
      return all_finite(scratch_);
    }

    bool computeJacobian(NOX::LAPACK::Matrix<double> &jacobian,
                         const NOX::LAPACK::Vector   &x) override
    {
      hb_.set_omega(omega_);
      hb_.evaluate(to_std(x), nullptr, &scratch_, nullptr);
      // Both column-major and contiguous: one block copy.
      std::copy(scratch_.begin(), scratch_.end(), &jacobian(0, 0));
      return all_finite(scratch_);
    }

    bool compute_domega(NOX::LAPACK::Vector &result, const NOX::LAPACK::Vector &x) override
    {
      hb_.set_omega(omega_);
      hb_.evaluate(to_std(x), nullptr, nullptr, &scratch_);
      for (unsigned int i = 0; i < scratch_.size(); ++i)
        result(i) = scratch_[i];
      return all_finite(scratch_);
    }

    void setParams(const LOCA::ParameterVector &p) override { omega_ = p.getValue("Omega"); }

    void printSolution(const NOX::LAPACK::Vector &x, const double omega) override
    {
      if (on_step)
        on_step(to_std(x), omega);
    }

    void set_omega(double omega) { omega_ = omega; }

    void record_linear_solve(const double seconds) override { hb_.record_linear_solve(seconds); }

    std::function<void(const std::vector<double> &, double)> on_step;

    static std::vector<double> to_std(const NOX::LAPACK::Vector &x)
    {
      std::vector<double> v(x.length());
      for (unsigned int i = 0; i < v.size(); ++i)
        v[i] = x(i);
      return v;
    }

  private:
    static bool all_finite(const std::vector<double> &v)
    {
      for (const double d : v)
        if (!std::isfinite(d))
          return false;
      return true;
    }

    HarmonicBalance    &hb_;
    NOX::LAPACK::Vector guess_;
    double              omega_ = 0;
    std::vector<double> scratch_;
  };

  /// Wall seconds since `start`, for the Newton steps' cost.
  double seconds_since(std::chrono::steady_clock::time_point start);

  /// Newton's stopping tests on the unscaled 2-norm of the HB residual.
  /// `tightening`: LOCA tests the norm of its extended (arclength) system,
  /// so it gets a tighter tolerance for the HB residual to meet the scene's.
  Teuchos::RCP<NOX::StatusTest::Generic>
  newton_status(const HarmonicBalanceParameters &params, double tightening = 1.0);

  /// Full Newton directions with the scene's line search; only errors printed.
  void set_newton_parameters(Teuchos::ParameterList &nox, const HarmonicBalanceParameters &params);
} // namespace nsm
