// NOX and LOCA glue: the HB system as a LOCA::LAPACK interface, Newton at
// fixed Omega, and LOCA's pseudo-arclength stepper with the analytic dR/dW.
#include <nsm/continuation.h>
#include <nsm/dense_lu.h>

#include <LOCA.H>
#include <LOCA_LAPACK.H>
#include <NOX.H>
#include <LOCA_MultiContinuation_ExtendedVector.H>
#include <NOX_LAPACK_Group.H>
#include <Teuchos_oblackholestream.hpp>

#include <chrono>
#include <cmath>

namespace nsm
{
  namespace
  {
    /// The HB system at the Omega LOCA or the Newton driver sets.
    class HbInterface : public LOCA::LAPACK::Interface
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
        const unsigned int n = x.length();
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            jacobian(i, j) = scratch_[i + j * n];
        return all_finite(scratch_);
      }

      bool compute_domega(NOX::LAPACK::Vector &result, const NOX::LAPACK::Vector &x)
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

    double seconds_since(std::chrono::steady_clock::time_point start)
    {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

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
        NOX::LAPACK::Matrix<double> lu    = jacSolver.getMatrix();
        newtonVector                      = fVector;
        isValidNewton = dense_solve(lu.numRows(), &lu(0, 0), &newtonVector(0));
        newtonVector.scale(-1.0);
        hb_.record_linear_solve(seconds_since(start));
        return isValidNewton ? NOX::Abstract::Group::Ok : NOX::Abstract::Group::Failed;
      }

    private:
      const HarmonicBalance &hb_;
    };

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

      NOX::Abstract::Group::ReturnType
      applyJacobianInverseMultiVector(Teuchos::ParameterList           &params,
                                      const NOX::Abstract::MultiVector &input,
                                      NOX::Abstract::MultiVector       &result) const override
      {
        const auto start = std::chrono::steady_clock::now();
        const auto status =
          LOCA::LAPACK::Group::applyJacobianInverseMultiVector(params, input, result);
        hb_.record_linear_solve(seconds_since(start));
        return status;
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
      HbInterface           &interface_;
      const HarmonicBalance &hb_;
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

    /// `tightening`: LOCA tests the norm of its extended (arclength) system,
    /// so it gets a tighter tolerance for the HB residual to meet the scene's.
    Teuchos::RCP<NOX::StatusTest::Generic>
    newton_status(const Scene::HarmonicBalance &params, double tightening = 1.0)
    {
      auto combo = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
      // Unscaled 2-norm: the same norm the points are accepted and written with.
      combo->addStatusTest(Teuchos::rcp(
        new NOX::StatusTest::NormF(params.tolerance * tightening, NOX::StatusTest::NormF::Unscaled)));
      combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::MaxIters(params.max_iterations)));
      // Newton on the exact rule converges quadratically once it converges at
      // all: a residual that has not halved in 6 steps in a row, or has blown
      // up, will not converge (and costs most of the time at folds).
      combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::Stagnation(6, 0.5)));
      combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::Divergence(1e8)));
      combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::FiniteValue));
      return combo;
    }

    void set_newton_parameters(Teuchos::ParameterList &nox, const Scene::HarmonicBalance &params)
    {
      nox.set("Nonlinear Solver", "Line Search Based");
      nox.sublist("Direction").set("Method", "Newton");
      nox.sublist("Line Search").set("Method", params.line_search);
      nox.sublist("Printing").set("Output Information", NOX::Utils::Error);
    }

    /// LOCA's parameters: pseudo-arclength in Omega from `start` over the
    /// scene's range and step bounds, Newton as at fixed Omega, and LOCA's
    /// own messages discarded.
    Teuchos::RCP<Teuchos::ParameterList>
    arclength_parameters(const Scene &scene, const BackbonePoint &start, const double initial_step)
    {
      const auto  &c         = scene.continuation;
      const double direction = branch_direction(scene);
      auto         params    = Teuchos::rcp(new Teuchos::ParameterList);
      auto        &stepper   = params->sublist("LOCA").sublist("Stepper");
      stepper.set("Continuation Method", "Arc Length");
      stepper.set("Continuation Parameter", "Omega");
      stepper.set("Initial Value", start.omega);
      stepper.set("Max Value", c.omega_max);
      stepper.set("Min Value", c.omega_min);
      stepper.set("Max Steps", static_cast<int>(c.max_steps));
      stepper.set("Max Nonlinear Iterations", static_cast<int>(scene.harmonic_balance.max_iterations));
      stepper.set("Compute Eigenvalues", false);
      params->sublist("LOCA").sublist("Predictor").set("Method", "Tangent");
      // Unscaled arclength: a step of length ds changes Omega by at most ds,
      // so Max step bounds the Omega increments as in sequential stepping.
      stepper.set("Enable Arc Length Scaling", false);
      auto &step = params->sublist("LOCA").sublist("Step Size");
      step.set("Method", "Adaptive");
      step.set("Aggressiveness", 1.0);
      step.set("Initial Step Size", direction * initial_step);
      step.set("Min Step Size", c.min_step);
      step.set("Max Step Size", c.max_step);
      set_newton_parameters(params->sublist("NOX"), scene.harmonic_balance);
      params->sublist("NOX").sublist("Printing").set("Output Information", NOX::Utils::Error);
      params->sublist("LOCA").sublist("Utilities").set("Output Information", NOX::Utils::Error);
      // LOCA always writes a failed step (Min step reached) to its error stream;
      // the run handles it as a fold and says so in its summary.
      const Teuchos::RCP<std::ostream> discard = Teuchos::rcp(new Teuchos::oblackholestream);
      params->sublist("NOX").sublist("Printing").set("Error Stream", discard);
      return params;
    }
  } // namespace

  struct NewtonSolver::Impl
  {
    Impl(HarmonicBalance &hb, const Scene::HarmonicBalance &params)
      : interface(hb, std::vector<double>(hb.n_unknowns(), 0.0))
      , group(Teuchos::rcp(new TimedNewtonGroup(interface, hb)))
      , status(newton_status(params))
      , list(Teuchos::rcp(new Teuchos::ParameterList))
      , max_iterations(params.max_iterations)
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

  NewtonSolver::NewtonSolver(HarmonicBalance &hb, const Scene::HarmonicBalance &params)
    : impl_(std::make_unique<Impl>(hb, params))
  {}

  NewtonSolver::~NewtonSolver() = default;

  NewtonResult NewtonSolver::solve(const double omega, const std::vector<double> &guess)
  {
    impl_->interface.set_omega(omega);
    impl_->interface.set_guess(guess);
    const auto start = std::chrono::steady_clock::now();
    impl_->solver->reset(impl_->interface.getInitialGuess());
    const NOX::StatusTest::StatusType status = impl_->solver->solve();
    const auto &group = impl_->solver->getSolutionGroup();
    const auto &x = dynamic_cast<const NOX::LAPACK::Vector &>(group.getX());
    const auto   iterations = static_cast<unsigned int>(impl_->solver->getNumIterations());
    NewtonResult result{status == NOX::StatusTest::Converged, iterations, group.getNormF(), HbInterface::to_std(x),
                        status != NOX::StatusTest::Converged && iterations >= impl_->max_iterations};
    const double seconds = seconds_since(start);
    (result.converged ? cost_.converged_seconds : cost_.failed_seconds) += seconds;
    ++(result.converged ? cost_.converged_solves : cost_.failed_solves);
    (result.converged ? cost_.converged_iterations : cost_.failed_iterations) += result.iterations;
    return result;
  }

  bool run_arclength(HarmonicBalance                                  &hb,
                     const Scene                                      &scene,
                     const BackbonePoint                              &start,
                     const double                                      initial_step,
                     const std::function<bool(const BackbonePoint &)> &accept)
  {
    const auto params   = arclength_parameters(scene, start, initial_step);
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
      status->addStatusTest(newton_status(scene.harmonic_balance, 0.1));
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
