#include <nsm/scene/bar_parameters.h>
#include <nsm/scene/scene_entries.h>

#include <deal.II/base/parameter_handler.h>

namespace nsm
{
  namespace
  {
    using namespace scene_entries;
  } // namespace

  void BarParameters::declare(ParameterHandler &prm)
  {
    const BarParameters d;
    prm.enter_subsection("Bar");
    prm.declare_entry("Length", text(d.length), dimensional(), "Bar length L.");
    prm.declare_entry("Young modulus", text(d.young_modulus), dimensional(), "Young modulus E.");
    prm.declare_entry("Density", text(d.density), dimensional(), "Mass density rho.");
    prm.declare_entry("Cross section",
                      d.cross_section,
                      Patterns::Anything(),
                      "Cross-section area A(x), a muparser expression in x (constants pi and L "
                      "available); 1e-20 <= A(x) <= 1e20 on [0, L].");
    prm.leave_subsection();
  }

  void BarParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Bar");
    length        = prm.get_double("Length");
    young_modulus = prm.get_double("Young modulus");
    density       = prm.get_double("Density");
    cross_section = prm.get("Cross section");
    prm.leave_subsection();
  }
} // namespace nsm
