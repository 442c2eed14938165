#include <nsm/scene/receptance_parameters.h>
#include <nsm/scene/scene_entries.h>

#include <deal.II/base/parameter_handler.h>

namespace nsm
{
  namespace
  {
    using namespace scene_entries;

    const Options<ReceptanceMethod> receptance_methods = {{"direct", ReceptanceMethod::direct},
                                                          {"modal", ReceptanceMethod::modal}};
  } // namespace

  void ReceptanceParameters::declare(ParameterHandler &prm)
  {
    const ReceptanceParameters d;
    prm.enter_subsection("Receptance");
    prm.declare_entry("Method",
                      name_of(d.method, receptance_methods),
                      selection(receptance_methods),
                      "direct: one band LU of K - w^2 M per frequency; modal: the modes below the band "
                      "once, then the modal sum.");
    prm.declare_entry("Modes",
                      text(d.modes),
                      Patterns::Integer(0, 10000000),
                      "Modal basis size, 0 = all; a truncated basis gets a static correction.");
    prm.leave_subsection();
  }

  void ReceptanceParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Receptance");
    method = selected(prm.get("Method"), receptance_methods);
    modes  = get_unsigned(prm, "Modes");
    prm.leave_subsection();
  }
} // namespace nsm
