#include <nsm/base/dense_lu.h>
#include <nsm/harmonic_balance/newton_solver.h>
#include <nsm/harmonic_balance/nox_hb_system.h>

#include <NOX_LAPACK_Group.H>

#include <vector>

namespace nsm
{
  namespace
  {
    /// NOX's LAPACK group, with its Newton step (LU of J and solve) timed and
    /// solved by dense_solve rather than the reference LAPACK's dgetrf.
    class TimedNewtonGroup : public NOX::LAPACK::Group
    {
    public:
      TimedNewtonGroup(HbInterface &interface, const HarmonicBalance &hb)
        : NOX::LAPACK::Group(interface)
        , hb_(hb)
      {}
      TimedNewtonGroup(const TimedNewtonGroup &source, NOX::CopyType type)
        : NOX::LAPACK::Group(source, type)
        , hb_(source.hb_)
      {}

      Teuchos::RCP<NOX::Abstract::Group> clone(NOX::CopyType type) const override
      {
        return Teuchos::rcp(new TimedNewtonGroup(*this, type));
      }

      NOX::Abstract::Group::ReturnType computeNewton(Teuchos::ParameterList &params) override
      {
        if (isNewton() || !isF() || !isJacobian())
          return NOX::LAPACK::Group::computeNewton(params);
        const auto                 start = std::chrono::steady_clock::now();
        // J is factored in a copy (the group keeps J), held from step to step.
        const NOX::LAPACK::Matrix<double> &jacobian = jacSolver.getMatrix();
        const int                          n        = jacobian.numRows();
        lu_.assign(&jacobian(0, 0), &jacobian(0, 0) + std::size_t(n) * n);
        newtonVector  = fVector;
        isValidNewton = dense_solve(n, lu_.data(), &newtonVector(0));
        newtonVector.scale(-1.0);
        hb_.record_linear_solve(seconds_since(start));
        return isValidNewton ? NOX::Abstract::Group::Ok : NOX::Abstract::Group::Failed;
      }

    private:
      const HarmonicBalance &hb_;
      std::vector<double>    lu_;
    };
  } // namespace

  struct NewtonSolver::Impl
  {
    Impl(HarmonicBalance &hb, const HarmonicBalanceParameters &params)
      : interface(hb, std::vector<double>(hb.n_unknowns(), 0.0))
      , group(Teuchos::rcp(new TimedNewtonGroup(interface, hb)))
      , status(newton_status(params))
      , list(Teuchos::rcp(new Teuchos::ParameterList))
      , max_iterations(params.iterations())
    {
      set_newton_parameters(*list, params);
      solver = NOX::Solver::buildSolver(group, status, list);
    }
    HbInterface                            interface;
    Teuchos::RCP<TimedNewtonGroup>         group;
    Teuchos::RCP<NOX::StatusTest::Generic> status;
    Teuchos::RCP<Teuchos::ParameterList>   list;
    Teuchos::RCP<NOX::Solver::Generic>     solver;
    unsigned int                           max_iterations;
  };

  NewtonSolver::NewtonSolver(HarmonicBalance &hb, const HarmonicBalanceParameters &params)
    : impl_(std::make_unique<Impl>(hb, params))
  {}

  NewtonSolver::~NewtonSolver() = default;

  NewtonResult NewtonSolver::solve(const double omega, const std::vector<double> &guess)
  {
    impl_->interface.set_omega(omega);
    impl_->interface.set_guess(guess);
    const auto start = std::chrono::steady_clock::now();
    impl_->solver->reset(impl_->interface.getInitialGuess());
    const NOX::StatusTest::StatusType status     = impl_->solver->solve();
    const auto                       &group      = impl_->solver->getSolutionGroup();
    const auto                       &x          = dynamic_cast<const NOX::LAPACK::Vector &>(group.getX());
    const auto                        iterations = static_cast<unsigned int>(impl_->solver->getNumIterations());
    NewtonResult result{status == NOX::StatusTest::Converged, iterations, group.getNormF(), HbInterface::to_std(x),
                        status != NOX::StatusTest::Converged && iterations >= impl_->max_iterations};
    const double seconds = seconds_since(start);
    (result.converged ? cost_.converged_seconds : cost_.failed_seconds) += seconds;
    ++(result.converged ? cost_.converged_solves : cost_.failed_solves);
    (result.converged ? cost_.converged_iterations : cost_.failed_iterations) += result.iterations;
    return result;
  }
} // namespace nsm
