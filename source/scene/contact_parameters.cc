#include <nsm/scene/contact_parameters.h>
#include <nsm/scene/scene_entries.h>

#include <deal.II/base/parameter_handler.h>

namespace nsm
{
  namespace
  {
    using namespace scene_entries;

    const Options<ForceSign> force_signs = {{"physical", ForceSign::physical},
                                            {"seed-eq5", ForceSign::seed_eq5}};
    const Options<Wall> walls = {{"rigid", Wall::rigid}, {"compliant", Wall::compliant}};
  } // namespace

  std::string wall_name(const Wall wall) { return name_of(wall, walls); }

  void ContactParameters::declare(ParameterHandler &prm)
  {
    const ContactParameters d;
    prm.enter_subsection("Contact");
    prm.declare_entry("Enabled", text(d.enabled), Patterns::Bool(), "A wall at x = L + gap; a backbone needs it.");
    prm.declare_entry("Gap", text(d.gap), dimensional(), "Initial gap g0.");
    prm.declare_entry("Alpha",
                      text(d.alpha),
                      dimensional(),
                      "alpha of the rigid wall's law -lambda + max(lambda - alpha g, 0) = 0 (a stiffness: it "
                      "scales the gap against the force in the switch).");
    prm.declare_entry("Force sign",
                      name_of(d.sign, force_signs),
                      selection(force_signs),
                      "physical: the wall pushes the bar back, u_N = -gamma lambda; seed-eq5: the "
                      "paper's eq. (5) literally, u_N = +gamma lambda.");
    prm.declare_entry("Wall",
                      name_of(d.wall, walls),
                      selection(walls),
                      "rigid: Signorini's law, lambda >= 0, g >= 0, lambda g = 0; compliant: a unilateral spring, "
                      "lambda = k max(-g, 0), solved as -lambda + max(-k g, 0) = 0 (doc/method.md, The wall).");
    prm.declare_entry("Wall stiffness",
                      text(d.stiffness),
                      dimensional(),
                      "k of a compliant wall, force per length; the rigid wall is its limit k -> infinity. The "
                      "bar's own static end stiffness is 1 / gamma(0) (E A / L for a uniform bar).");
    prm.leave_subsection();
  }

  void ContactParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Contact");
    enabled = prm.get_bool("Enabled");
    gap     = prm.get_double("Gap");
    alpha   = prm.get_double("Alpha");
    sign    = selected(prm.get("Force sign"), force_signs);
    wall      = selected(prm.get("Wall"), walls);
    stiffness = prm.get_double("Wall stiffness");
    prm.leave_subsection();
  }
} // namespace nsm
