#include <nsm/scene/harmonic_balance_parameters.h>
#include <nsm/scene/scene_entries.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <string>

namespace nsm
{
  namespace
  {
    using namespace scene_entries;

    const Options<HarmonicBasis> bases = {{"cosine", HarmonicBasis::cosine},
                                          {"full", HarmonicBasis::full}};
    const Options<Integration> integrations = {{"sampled", Integration::sampled},
                                               {"exact", Integration::exact}};
  } // namespace

  void HarmonicBalanceParameters::declare(ParameterHandler &prm)
  {
    const HarmonicBalanceParameters d;
    prm.enter_subsection("Harmonic balance");
    prm.declare_entry("Harmonics", text(d.harmonics), Patterns::Integer(1, 1000), "M.");
    prm.declare_entry("Time samples",
                      text(d.time_samples),
                      Patterns::Integer(0, 1 << 20),
                      "Samples per period; 0 = smallest power of two >= 16 M; otherwise >= 2 M + 1.");
    prm.declare_entry("Basis",
                      name_of(d.basis, bases),
                      selection(bases),
                      "cosine: motions even in time; full: sine and cosine with a phase condition.");
    prm.declare_entry("Integration",
                      name_of(d.integration, integrations),
                      selection(integrations),
                      "sampled: discrete Fourier transform of max(lambda - alpha g, 0) at the "
                      "samples; exact: integrals between the roots of lambda - alpha g.");
    prm.declare_entry("Tolerance",
                      text(d.tolerance),
                      Patterns::Double(1e-15, 1e-6),
                      "Newton tolerance on the scaled residual norm; a looser one would write "
                      "points that solve nothing.");
    prm.declare_entry("Max iterations",
                      text(d.max_iterations),
                      Patterns::Integer(0, 1000),
                      "Newton iterations per solve; 0 = max(12, M / 16): converging solves take more "
                      "iterations as M grows.");
    prm.declare_entry("Line search",
                      d.line_search,
                      Patterns::Selection("Full Step|Backtrack|Polynomial"),
                      "NOX line search method.");
    prm.leave_subsection();
  }

  void HarmonicBalanceParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Harmonic balance");
    harmonics    = get_unsigned(prm, "Harmonics");
    time_samples = get_unsigned(prm, "Time samples");
    require(time_samples == 0 || time_samples >= 2 * harmonics + 1,
            "Harmonic balance/Time samples",
            "0 or an integer in [2 M + 1, 2^20] = [" + std::to_string(2 * harmonics + 1) +
              ", 1048576]",
            std::to_string(time_samples));
    basis          = selected(prm.get("Basis"), bases);
    integration    = selected(prm.get("Integration"), integrations);
    tolerance      = prm.get_double("Tolerance");
    max_iterations = get_unsigned(prm, "Max iterations");
    line_search    = prm.get("Line search");
    prm.leave_subsection();
  }

  unsigned int HarmonicBalanceParameters::iterations() const
  {
    // The iterations the converged solves of the seed bar take (FE_Q(10),
    // sequential, to 2.2): at most 12 at M = 80 and 160 (a few at the limit), up
    // to 20 at M = 320, where 12 lose the branch at 2.1530 and 20 carry it to
    // 2.2 (doc/accuracy-and-cost.md, "M = 320"). So 12 up to M = 207, then M / 16.
    constexpr unsigned int least = 12, harmonics_per_iteration = 16;
    return max_iterations != 0 ? max_iterations : std::max(least, harmonics / harmonics_per_iteration);
  }

  unsigned int HarmonicBalanceParameters::samples() const
  {
    if (time_samples != 0)
      return time_samples;
    unsigned int n = 1;
    while (n < 16 * harmonics)
      n *= 2;
    return n;
  }
} // namespace nsm
