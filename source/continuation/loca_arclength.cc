#include <nsm/continuation/constants.h>
#include <nsm/continuation/dense_lu_group.h>
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
      auto group = Teuchos::rcp(new DenseLuGroup(data, interface));
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
