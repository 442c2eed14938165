#include <nsm/base/dense_lu.h>
#include <nsm/continuation/dense_lu_group.h>

#include <algorithm>
#include <chrono>

namespace nsm
{
  DenseLuGroup::DenseLuGroup(const Teuchos::RCP<LOCA::GlobalData> &data, LocaSystem &system)
    : LOCA::LAPACK::Group(data, system)
    , system_(system)
  {}

  DenseLuGroup::DenseLuGroup(const DenseLuGroup &source, NOX::CopyType type)
    : LOCA::LAPACK::Group(source, type)
    , system_(source.system_)
  {}

  NOX::Abstract::Group::ReturnType
  DenseLuGroup::applyJacobianInverseMultiVector(Teuchos::ParameterList &, const NOX::Abstract::MultiVector &input,
                                                NOX::Abstract::MultiVector &result) const
  {
    return timed_solves(input.numVectors(), [&](const int c) { solve(input[c], result[c]); });
  }

  NOX::Abstract::Group::ReturnType DenseLuGroup::applyJacobianInverse(Teuchos::ParameterList &,
                                                                     const NOX::Abstract::Vector &input,
                                                                     NOX::Abstract::Vector       &result) const
  {
    return timed_solves(1, [&](int) { solve(input, result); });
  }

  Teuchos::RCP<NOX::Abstract::Group> DenseLuGroup::clone(NOX::CopyType type) const
  {
    return Teuchos::rcp(new DenseLuGroup(*this, type));
  }

  NOX::Abstract::Group::ReturnType DenseLuGroup::computeDfDpMulti(const std::vector<int> &parameters,
                                                                  NOX::Abstract::MultiVector &dfdp,
                                                                  const bool                  is_valid_f)
  {
    if (!is_valid_f)
      {
        if (computeF() != NOX::Abstract::Group::Ok)
          return NOX::Abstract::Group::Failed;
        dfdp[0] = getF();
      }
    system_.setParams(getParams());
    const auto &x = dynamic_cast<const NOX::LAPACK::Vector &>(getX());
    for (unsigned int i = 0; i < parameters.size(); ++i)
      if (!system_.compute_domega(dynamic_cast<NOX::LAPACK::Vector &>(dfdp[i + 1]), x))
        return NOX::Abstract::Group::Failed;
    return NOX::Abstract::Group::Ok;
  }

  template <typename Solve>
  NOX::Abstract::Group::ReturnType DenseLuGroup::timed_solves(const int count, const Solve &solve_column) const
  {
    const auto start = std::chrono::steady_clock::now();
    const bool ok    = isJacobian() && factor();
    for (int c = 0; ok && c < count; ++c)
      solve_column(c);
    system_.record_linear_solve(seconds_since(start));
    return ok ? NOX::Abstract::Group::Ok : NOX::Abstract::Group::Failed;
  }

  void DenseLuGroup::solve(const NOX::Abstract::Vector &input, NOX::Abstract::Vector &result) const
  {
    auto &x = dynamic_cast<NOX::LAPACK::Vector &>(result);
    x       = dynamic_cast<const NOX::LAPACK::Vector &>(input);
    lu_solve(x.length(), factors_.data(), pivots_.data(), &x(0));
  }

  bool DenseLuGroup::factor() const
  {
    const NOX::LAPACK::Matrix<double> &jacobian = jacSolver.getMatrix();
    const int                          n        = jacobian.numRows();
    const double                      *a        = &jacobian(0, 0);
    if (factored_ && std::equal(a, a + std::size_t(n) * n, matrix_.begin()))
      return true;
    matrix_.assign(a, a + std::size_t(n) * n);
    factors_ = matrix_;
    pivots_.resize(n);
    factored_ = lu_factor(n, factors_.data(), pivots_.data());
    return factored_;
  }
} // namespace nsm
