#include <nsm/continuation/constants.h>
#include <nsm/continuation/forced_response.h>
#include <nsm/harmonic_balance/nox_hb_system.h>

#include <LOCA.H>
#include <LOCA_LAPACK.H>
#include <LOCA_MultiContinuation_ExtendedVector.H>
#include <Teuchos_oblackholestream.hpp>

#include <cmath>

namespace nsm
{
  namespace
  {
    /// The forced system at the W LOCA sets; dR/dW by LOCA's finite differences.
    class ForcedInterface : public LOCA::LAPACK::Interface
    {
    public:
      explicit ForcedInterface(ForcedHarmonicBalance &hb)
        : hb_(hb)
        , guess_(hb.n_unknowns())
      {}

      const NOX::LAPACK::Vector &getInitialGuess() override { return guess_; }

      bool computeF(NOX::LAPACK::Vector &f, const NOX::LAPACK::Vector &x) override
      {
        hb_.set_omega(omega_);
        hb_.evaluate(HbInterface::to_std(x), &scratch_, nullptr);
        return copy(scratch_, &f(0));
      }

      bool computeJacobian(NOX::LAPACK::Matrix<double> &jacobian, const NOX::LAPACK::Vector &x) override
      {
        hb_.set_omega(omega_);
        hb_.evaluate(HbInterface::to_std(x), nullptr, &scratch_);
        return copy(scratch_, &jacobian(0, 0));
      }

      void setParams(const LOCA::ParameterVector &p) override { omega_ = p.getValue("Omega"); }

      void printSolution(const NOX::LAPACK::Vector &x, const double omega) override
      {
        if (on_step)
          on_step(HbInterface::to_std(x), omega);
      }

      std::function<void(const std::vector<double> &, double)> on_step;

    private:
      static bool copy(const std::vector<double> &from, double *to)
      {
        bool finite = true;
        for (std::size_t i = 0; i < from.size(); ++i)
          finite = finite && std::isfinite(to[i] = from[i]);
        return finite;
      }

      ForcedHarmonicBalance &hb_;
      NOX::LAPACK::Vector    guess_;
      double                 omega_ = 0;
      std::vector<double>    scratch_;
    };

    /// Newton's tests, and where they converge, the step's guard: a step
    /// whose contact fraction moved more than Max contact change from the
    /// last point written fails, and LOCA retries it shorter. Without it a
    /// step of Max step passes over the fold of a curve whose peak is a few
    /// steps wide, onto the curve's other side (seen on the seed bar).
    class GuardedStep : public NOX::StatusTest::Generic
    {
    public:
      GuardedStep(Teuchos::RCP<NOX::StatusTest::Generic> newton, ForcedHarmonicBalance &hb,
                  const double max_contact_change, const double &last_contact)
        : newton_(newton)
        , hb_(hb)
        , max_change_(max_contact_change)
        , last_contact_(last_contact)
      {}

      NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic &problem,
                                              NOX::StatusTest::CheckType  type) override
      {
        status_ = newton_->checkStatus(problem, type);
        if (status_ != NOX::StatusTest::Converged || std::isnan(last_contact_))
          return status_;
        const auto &extended =
          dynamic_cast<const LOCA::MultiContinuation::ExtendedVector &>(problem.getSolutionGroup().getX());
        const auto &x = dynamic_cast<const NOX::LAPACK::Vector &>(*extended.getXVec());
        hb_.set_omega(extended.getScalar(0));
        const double contact = hb_.measure(HbInterface::to_std(x)).contact_fraction;
        if (std::abs(contact - last_contact_) > max_change_)
          status_ = NOX::StatusTest::Failed;
        return status_;
      }

      NOX::StatusTest::StatusType getStatus() const override { return status_; }

      std::ostream &print(std::ostream &stream, int indent) const override
      {
        return stream << std::string(indent, ' ') << status_ << " contact fraction within Max contact change\n";
      }

    private:
      Teuchos::RCP<NOX::StatusTest::Generic> newton_;
      ForcedHarmonicBalance                 &hb_;
      double                                 max_change_;
      const double                          &last_contact_;
      NOX::StatusTest::StatusType            status_ = NOX::StatusTest::Unevaluated;
    };

    /// LOCA's parameters: pseudo-arclength in W over the range with the
    /// scene's step bounds, Newton as the backbone's, LOCA's messages discarded.
    Teuchos::RCP<Teuchos::ParameterList> forced_parameters(const HarmonicBalanceParameters &hb,
                                                           const ContinuationParameters    &c,
                                                           const double omega_min, const double omega_max)
    {
      auto  params  = Teuchos::rcp(new Teuchos::ParameterList);
      auto &stepper = params->sublist("LOCA").sublist("Stepper");
      stepper.set("Continuation Method", "Arc Length");
      stepper.set("Continuation Parameter", "Omega");
      stepper.set("Initial Value", omega_min);
      stepper.set("Max Value", omega_max);
      stepper.set("Min Value", omega_min);
      stepper.set("Max Steps", static_cast<int>(c.max_steps));
      stepper.set("Max Nonlinear Iterations", static_cast<int>(hb.iterations()));
      stepper.set("Compute Eigenvalues", false);
      stepper.set("Enable Arc Length Scaling", false);
      params->sublist("LOCA").sublist("Predictor").set("Method", "Tangent");
      auto &step = params->sublist("LOCA").sublist("Step Size");
      step.set("Method", "Adaptive");
      step.set("Aggressiveness", continuation_constants::loca_aggressiveness);
      step.set("Initial Step Size", c.initial_step);
      step.set("Min Step Size", c.min_step);
      step.set("Max Step Size", c.max_step);
      set_newton_parameters(params->sublist("NOX"), hb);
      params->sublist("NOX").sublist("Printing").set("Output Information", NOX::Utils::Error);
      params->sublist("LOCA").sublist("Utilities").set("Output Information", NOX::Utils::Error);
      params->sublist("NOX").sublist("Printing").set("Error Stream",
                                                      Teuchos::RCP<std::ostream>(new Teuchos::oblackholestream));
      return params;
    }
  } // namespace

  ForcedCurve trace_forced_curve(ForcedHarmonicBalance           &hb,
                                 const HarmonicBalanceParameters &harmonic_balance,
                                 const ContinuationParameters    &continuation,
                                 const double                     omega_min,
                                 const double                     omega_max,
                                 const double                     forcing)
  {
    hb.set_forcing(forcing);
    ForcedCurve curve;
    double      last_contact = std::nan(""); // none before the start
    curve.forcing     = forcing;
    const auto params = forced_parameters(harmonic_balance, continuation, omega_min, omega_max);
    auto       data   = LOCA::createGlobalData(params);
    {
      ForcedInterface interface(hb);
      auto            group = Teuchos::rcp(new LOCA::LAPACK::Group(data, interface));
      LOCA::ParameterVector parameters;
      parameters.addParameter("Omega", omega_min);
      group->setParams(parameters);
      interface.on_step = [&](const std::vector<double> &x, const double omega) {
        hb.set_omega(omega);
        std::vector<double> residual;
        hb.evaluate(x, &residual, nullptr);
        double norm = 0;
        for (const double r : residual)
          norm += r * r;
        norm = std::sqrt(norm);
        if (norm > harmonic_balance.tolerance)
          ++curve.rejected;
        else
          {
            curve.points.push_back({omega, hb.measure(x), norm, x});
            last_contact = curve.points.back().measures.contact_fraction;
          }
      };
      const auto status = Teuchos::rcp(new GuardedStep(
        newton_status(harmonic_balance), hb,
        continuation.max_contact_change, last_contact));
      LOCA::Stepper stepper(data, group, status, params);
      curve.finished = stepper.run() == LOCA::Abstract::Iterator::Finished;
    }
    LOCA::destroyGlobalData(data);
    return curve;
  }
} // namespace nsm
