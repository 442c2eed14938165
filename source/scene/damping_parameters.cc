#include <nsm/scene/damping_parameters.h>
#include <nsm/scene/scene_entries.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>

namespace nsm
{
  namespace
  {
    using namespace scene_entries;
  } // namespace

  double DampingParameters::coefficient(const double eigenvalue) const
  {
    return 2 * modal_ratio * std::sqrt(eigenvalue) + rayleigh_alpha + rayleigh_beta * eigenvalue;
  }

  void DampingParameters::declare(ParameterHandler &prm)
  {
    const DampingParameters d;
    prm.enter_subsection("Damping");
    prm.declare_entry("Modal ratio",
                      text(d.modal_ratio),
                      Patterns::Double(0, 1),
                      "zeta: every mode j of the FE model gets the damping 2 zeta w_j (a ratio of critical "
                      "damping). Only the forced response (Forcing/Amplitudes) is damped.");
    prm.declare_entry("Rayleigh alpha",
                      text(d.rayleigh_alpha),
                      Patterns::Double(0, magnitude_limit),
                      "alpha of C = alpha M + beta K, per unit time; adds to Modal ratio.");
    prm.declare_entry("Rayleigh beta",
                      text(d.rayleigh_beta),
                      Patterns::Double(0, magnitude_limit),
                      "beta of C = alpha M + beta K, a time; adds to Modal ratio.");
    prm.leave_subsection();
  }

  void DampingParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Damping");
    modal_ratio    = prm.get_double("Modal ratio");
    rayleigh_alpha = prm.get_double("Rayleigh alpha");
    rayleigh_beta  = prm.get_double("Rayleigh beta");
    prm.leave_subsection();
  }
} // namespace nsm
