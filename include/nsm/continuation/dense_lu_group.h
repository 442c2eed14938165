// LOCA's LAPACK group for the systems this project continues in Omega (the
// backbone's harmonic balance, the forced response's): dR/dW from the system
// instead of finite differences, and J^-1 by this project's LU
// (base/dense_lu.h) instead of LAPACK's dgetrf and dgetrs, timed.
#pragma once

#include <nsm/harmonic_balance/nox_hb_system.h>

#include <LOCA_LAPACK.H>

#include <vector>

namespace nsm
{
  class DenseLuGroup : public LOCA::LAPACK::Group
  {
  public:
    DenseLuGroup(const Teuchos::RCP<LOCA::GlobalData> &data, LocaSystem &system);
    DenseLuGroup(const DenseLuGroup &source, NOX::CopyType type);

    /// J^-1 on each column: 183 against 495 us per solve at M = 160
    /// (benchmark_high_harmonics arclength 160). The factors are kept with
    /// the matrix they factor, and redone when the group's Jacobian differs
    /// from it (LOCA copies and assigns groups).
    NOX::Abstract::Group::ReturnType applyJacobianInverseMultiVector(Teuchos::ParameterList &,
                                                                     const NOX::Abstract::MultiVector &input,
                                                                     NOX::Abstract::MultiVector &result) const override;

    using LOCA::LAPACK::Group::applyJacobianInverse;
    NOX::Abstract::Group::ReturnType applyJacobianInverse(Teuchos::ParameterList &, const NOX::Abstract::Vector &input,
                                                          NOX::Abstract::Vector &result) const override;

    Teuchos::RCP<NOX::Abstract::Group> clone(NOX::CopyType type) const override;

    /// dR/dW from the system (the one parameter, Omega).
    NOX::Abstract::Group::ReturnType computeDfDpMulti(const std::vector<int> &parameters,
                                                      NOX::Abstract::MultiVector &dfdp, bool is_valid_f) override;

  private:
    /// `count` solves by solve_column(c), after the Jacobian's LU; timed.
    template <typename Solve>
    NOX::Abstract::Group::ReturnType timed_solves(int count, const Solve &solve_column) const;

    /// result = J^-1 input, from the kept factors.
    void solve(const NOX::Abstract::Vector &input, NOX::Abstract::Vector &result) const;

    /// LU of the current Jacobian, unless the kept factors are of it.
    bool factor() const;

    LocaSystem                 &system_;
    mutable std::vector<double> matrix_, factors_;
    mutable std::vector<int>    pivots_;
    mutable bool                factored_ = false;
  };
} // namespace nsm
