#include <nsm/base/dense_lu.h>
#include <nsm/continuation/constants.h>
#include <nsm/continuation/loca_arclength.h>
#include <nsm/harmonic_balance/nox_hb_system.h>

#include <LOCA.H>
#include <LOCA_MultiContinuation_ExtendedVector.H>
#include <Teuchos_oblackholestream.hpp>

#include <algorithm>
#include <cmath>

namespace nsm
{
  namespace
  {
    /// LOCA's LAPACK group with dR/dW from the HB module instead of finite
    /// differences, and its linear solves timed.
    class HbGroup : public LOCA::LAPACK::Group
    {
    public:
      HbGroup(const Teuchos::RCP<LOCA::GlobalData> &data, HbInterface &interface,
              const HarmonicBalance &hb)
        : LOCA::LAPACK::Group(data, interface)
        , interface_(interface)
        , hb_(hb)
      {}
      HbGroup(const HbGroup &source, NOX::CopyType type)
        : LOCA::LAPACK::Group(source, type)
        , interface_(source.interface_)
        , hb_(source.hb_)
      {}

      /// J^-1 on each column, by this project's LU (base/dense_lu.h) instead
      /// of LAPACK's dgetrf and dgetrs: 183 against 495 us per solve at
      /// M = 160 (benchmark_high_harmonics arclength 160). The
      /// factors are kept with the matrix they factor, and redone when the
      /// group's Jacobian differs from it (LOCA copies and assigns groups).
      NOX::Abstract::Group::ReturnType
      applyJacobianInverseMultiVector(Teuchos::ParameterList &, const NOX::Abstract::MultiVector &input,
                                      NOX::Abstract::MultiVector &result) const override
      {
        return timed_solves(input.numVectors(), [&](const int c) { solve(input[c], result[c]); });
      }

      using LOCA::LAPACK::Group::applyJacobianInverse;
      NOX::Abstract::Group::ReturnType applyJacobianInverse(Teuchos::ParameterList &, const NOX::Abstract::Vector &input,
                                                            NOX::Abstract::Vector &result) const override
      {
        return timed_solves(1, [&](int) { solve(input, result); });
      }

      Teuchos::RCP<NOX::Abstract::Group> clone(NOX::CopyType type) const override
      {
        return Teuchos::rcp(new HbGroup(*this, type));
      }

      NOX::Abstract::Group::ReturnType
      computeDfDpMulti(const std::vector<int> &parameters,
                       NOX::Abstract::MultiVector &dfdp,
                       bool is_valid_f) override
      {
        if (!is_valid_f)
          {
            if (computeF() != NOX::Abstract::Group::Ok)
              return NOX::Abstract::Group::Failed;
            dfdp[0] = getF();
          }
        interface_.setParams(getParams());
        const auto &x = dynamic_cast<const NOX::LAPACK::Vector &>(getX());
        for (unsigned int i = 0; i < parameters.size(); ++i)
          if (!interface_.compute_domega(dynamic_cast<NOX::LAPACK::Vector &>(dfdp[i + 1]), x))
            return NOX::Abstract::Group::Failed;
        return NOX::Abstract::Group::Ok;
      }

    private:
      /// `count` solves by solve_column(c), after the Jacobian's LU; timed.
      template <typename Solve>
      NOX::Abstract::Group::ReturnType timed_solves(const int count, const Solve &solve_column) const
      {
        const auto start = std::chrono::steady_clock::now();
        const bool ok    = isJacobian() && factor();
        for (int c = 0; ok && c < count; ++c)
          solve_column(c);
        hb_.record_linear_solve(seconds_since(start));
        return ok ? NOX::Abstract::Group::Ok : NOX::Abstract::Group::Failed;
      }

      /// result = J^-1 input, from the kept factors.
      void solve(const NOX::Abstract::Vector &input, NOX::Abstract::Vector &result) const
      {
        auto &x = dynamic_cast<NOX::LAPACK::Vector &>(result);
        x       = dynamic_cast<const NOX::LAPACK::Vector &>(input);
        lu_solve(x.length(), factors_.data(), pivots_.data(), &x(0));
      }

      /// LU of the current Jacobian, unless the kept factors are of it.
      bool factor() const
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

      HbInterface           &interface_;
      const HarmonicBalance &hb_;
      mutable std::vector<double> matrix_, factors_;
      mutable std::vector<int>    pivots_;
      mutable bool                factored_ = false;
    };

    /// Fails a LOCA step whose iterate has left contact: the trivial motion
    /// solves the HB equations at every Omega, and a step onto it must be
    /// retried shorter rather than accepted.
    class StaysInContact : public NOX::StatusTest::Generic
    {
    public:
      explicit StaysInContact(HarmonicBalance &hb)
        : hb_(hb)
      {}

      NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic &problem,
                                              NOX::StatusTest::CheckType) override
      {
        const auto &extended =
          dynamic_cast<const LOCA::MultiContinuation::ExtendedVector &>(
            problem.getSolutionGroup().getX());
        const auto &x = dynamic_cast<const NOX::LAPACK::Vector &>(*extended.getXVec());
        hb_.set_omega(extended.getScalar(0));
        status_ = hb_.contact_fraction(HbInterface::to_std(x)) > 0 ? NOX::StatusTest::Unconverged :
                                                                     NOX::StatusTest::Failed;
        return status_;
      }

      NOX::StatusTest::StatusType getStatus() const override { return status_; }

      std::ostream &print(std::ostream &stream, int indent) const override
      {
        return stream << std::string(indent, ' ') << status_ << " iterate in contact\n";
      }

    private:
      HarmonicBalance            &hb_;
      NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
    };

    /// LOCA's parameters: pseudo-arclength in Omega from `start` over the
    /// scene's range and step bounds, Newton as at fixed Omega, and LOCA's
    /// own messages discarded.
    Teuchos::RCP<Teuchos::ParameterList>
    arclength_parameters(const BranchParameters &branch, const BackbonePoint &start, const double initial_step)
    {
      const auto  &c         = branch.continuation;
      const double direction = branch_direction(branch.contact);
      auto         params    = Teuchos::rcp(new Teuchos::ParameterList);
      auto        &stepper   = params->sublist("LOCA").sublist("Stepper");
      stepper.set("Continuation Method", "Arc Length");
      stepper.set("Continuation Parameter", "Omega");
      stepper.set("Initial Value", start.omega);
      stepper.set("Max Value", c.omega_max);
      stepper.set("Min Value", c.omega_min);
      stepper.set("Max Steps", static_cast<int>(c.max_steps));
      stepper.set("Max Nonlinear Iterations", static_cast<int>(branch.harmonic_balance.iterations()));
      stepper.set("Compute Eigenvalues", false);
      params->sublist("LOCA").sublist("Predictor").set("Method", "Tangent");
      // Unscaled arclength: a step of length ds changes Omega by at most ds,
      // so Max step bounds the Omega increments as in sequential stepping.
      stepper.set("Enable Arc Length Scaling", false);
      auto &step = params->sublist("LOCA").sublist("Step Size");
      step.set("Method", "Adaptive");
      step.set("Aggressiveness", continuation_constants::loca_aggressiveness);
      step.set("Initial Step Size", direction * initial_step);
      step.set("Min Step Size", c.min_step);
      step.set("Max Step Size", c.max_step);
      set_newton_parameters(params->sublist("NOX"), branch.harmonic_balance);
      params->sublist("NOX").sublist("Printing").set("Output Information", NOX::Utils::Error);
      params->sublist("LOCA").sublist("Utilities").set("Output Information", NOX::Utils::Error);
      // LOCA always writes a failed step (Min step reached) to its error stream;
      // the run handles it as a fold and says so in its summary.
      const Teuchos::RCP<std::ostream> discard = Teuchos::rcp(new Teuchos::oblackholestream);
      params->sublist("NOX").sublist("Printing").set("Error Stream", discard);
      return params;
    }
  } // namespace

  bool run_arclength(HarmonicBalance                                  &hb,
                     const BranchParameters                           &branch,
                     const BackbonePoint                              &start,
                     const double                                      initial_step,
                     const std::function<bool(const BackbonePoint &)> &accept)
  {
    const auto params   = arclength_parameters(branch, start, initial_step);
    auto       data     = LOCA::createGlobalData(params);
    bool       finished = true;
    {
      HbInterface interface(hb, start.x);
      interface.set_omega(start.omega);
      auto group = Teuchos::rcp(new HbGroup(data, interface, hb));
      LOCA::ParameterVector parameters;
      parameters.addParameter("Omega", start.omega);
      group->setParams(parameters);

      struct Stop
      {};
      unsigned int step_count = 0;
      interface.on_step = [&](const std::vector<double> &x, double omega) {
        if (step_count++ == 0)
          return; // LOCA reports its start point first: already accepted
        hb.set_omega(omega);
        std::vector<double> residual;
        hb.evaluate(x, &residual, nullptr, nullptr);
        double norm = 0;
        for (const double r : residual)
          norm += r * r;
        BackbonePoint point{start.segment, omega, hb.measure(x), 0, std::sqrt(norm), x};
        if (!accept(point))
          throw Stop();
      };
      auto status = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
      status->addStatusTest(newton_status(branch.harmonic_balance, continuation_constants::loca_corrector_tolerance_factor));
      status->addStatusTest(Teuchos::rcp(new StaysInContact(hb)));
      LOCA::Stepper locaStepper(data, group, status, params);
      try
        {
          finished = locaStepper.run() == LOCA::Abstract::Iterator::Finished;
        }
      catch (const Stop &)
        {}
    }
    LOCA::destroyGlobalData(data);
    return finished;
  }
} // namespace nsm
