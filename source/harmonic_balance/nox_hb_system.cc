#include <nsm/harmonic_balance/constants.h>
#include <nsm/harmonic_balance/nox_hb_system.h>

namespace nsm
{
  double seconds_since(std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  Teuchos::RCP<NOX::StatusTest::Generic>
  newton_status(const HarmonicBalanceParameters &params, const double tightening)
  {
    auto combo = Teuchos::rcp(new NOX::StatusTest::Combo(NOX::StatusTest::Combo::OR));
    // Unscaled 2-norm: the same norm the points are accepted and written with.
    combo->addStatusTest(Teuchos::rcp(
      new NOX::StatusTest::NormF(params.tolerance * tightening, NOX::StatusTest::NormF::Unscaled)));
    combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::MaxIters(params.iterations())));
    using namespace harmonic_balance_constants;
    combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::Stagnation(stagnation_steps, stagnation_ratio)));
    combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::Divergence(divergence_limit)));
    combo->addStatusTest(Teuchos::rcp(new NOX::StatusTest::FiniteValue));
    return combo;
  }

  void set_newton_parameters(Teuchos::ParameterList &nox, const HarmonicBalanceParameters &params)
  {
    nox.set("Nonlinear Solver", "Line Search Based");
    nox.sublist("Direction").set("Method", "Newton");
    nox.sublist("Line Search").set("Method", params.line_search);
    nox.sublist("Printing").set("Output Information", NOX::Utils::Error);
  }
} // namespace nsm
