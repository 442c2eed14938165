#include <nsm/scene/forcing_parameters.h>
#include <nsm/scene/scene_entries.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>

namespace nsm
{
  namespace
  {
    using namespace scene_entries;

    const Options<ForcingShape> shapes = {{"tip", ForcingShape::tip}, {"uniform", ForcingShape::uniform}};

    /// The comma list of Forcing/`entry`, one curve per value: each in
    /// (0, 1e20], no two equal, at most ForcingParameters::max_amplitudes of them.
    std::vector<double> curve_values(ParameterHandler &prm, const std::string &entry)
    {
      const std::string   name = "Forcing/" + entry;
      std::vector<double> values;
      for (const std::string &item : list_items(prm.get(entry), name))
        {
          const double v = parse_double(item, name);
          require(v > 0 && v <= magnitude_limit, name, "numbers in (0, 1e20]", item);
          // Two equal values would write two identical curves that frc.csv's
          // columns cannot tell apart.
          require(std::find(values.begin(), values.end(), v) == values.end(), name,
                  "distinct numbers (one curve each; this one is listed twice)", item);
          values.push_back(v);
          require(values.size() <= ForcingParameters::max_amplitudes, name,
                  "at most " + std::to_string(ForcingParameters::max_amplitudes) + " numbers (one curve each)",
                  "a longer list");
        }
      return values;
    }
  } // namespace

  void ForcingParameters::declare(ParameterHandler &prm)
  {
    prm.enter_subsection("Forcing");
    prm.declare_entry("Amplitudes",
                      "",
                      Patterns::Anything(),
                      "Force levels F of the drive F cos(W t) (at the contact end or per unit length: Shape; "
                      "along +x, towards the wall), comma-separated, at most 100, distinct, each in (0, 1e20]: one frequency-response curve each, "
                      "written to frc.csv over Continuation's Omega range; needs damping (Damping). Empty: "
                      "no frequency-response curve.");
    prm.declare_entry("Omegas",
                      "",
                      Patterns::Anything(),
                      "Drive frequencies W, comma-separated, at most 100, distinct, each in (0, 1e20]: one force-response "
                      "curve each, traced in F up to Amplitude max (through its folds: the jumps of a slow sweep "
                      "in force) with Continuation's steps as shares of its Omega range, written to "
                      "force_response.csv; needs damping. Empty: none.");
    const ForcingParameters d;
    prm.declare_entry("Shape",
                      name_of(d.shape, shapes),
                      selection(shapes),
                      "Where the drive acts: tip, F cos(W t) at the contact end (a force); uniform, F cos(W t) per "
                      "unit length along the whole bar (a force per length, whatever the section), which drives "
                      "mode j by F times its integral over the bar.");
    prm.declare_entry("Amplitude max",
                      text(d.amplitude_max),
                      Patterns::Double(0, magnitude_limit),
                      "The force-response curves' largest F; 0: the largest of Amplitudes (one of the two is "
                      "needed with Omegas).");
    prm.declare_entry("Verify every",
                      text(d.verify_every),
                      Patterns::Integer(0, 1000000),
                      "Integrate every n-th point of each forced curve in time (the damped, driven model with "
                      "the physical wall, Output/Verify steps per period, from the point's own motion) and write "
                      "the last period's tip amplitude and energy to frc.csv; 0 = none.");
    prm.declare_entry("Verify periods",
                      text(d.verify_periods),
                      Patterns::Integer(0, max_verify_periods),
                      "Periods integrated from each verified point; the last one is compared with the point. 0: "
                      "to steady state, the periods in which the slowest mode's free motion decays to 1e-3 of its "
                      "start (ln(1000) / (min_j c_j / 2) / T; about 550 with Modal ratio 0.002), at most 100000.");
    prm.declare_entry("Floquet",
                      text(d.floquet),
                      Patterns::Bool(),
                      "At every point verified in time (Verify every), also the Floquet multipliers: the stepped "
                      "model's periodic orbit found by shooting from the point, and its monodromy's eigenvalues "
                      "(frc.csv's floquet_ columns; folds, period doublings and Neimark-Sacker pairs as events). Needs "
                      "Contact/Wall = compliant and Verify every > 0.");
    prm.leave_subsection();
  }

  void ForcingParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Forcing");
    shape          = selected(prm.get("Shape"), shapes);
    verify_every   = get_unsigned(prm, "Verify every");
    verify_periods = get_unsigned(prm, "Verify periods");
    floquet        = prm.get_bool("Floquet");
    amplitude_max  = prm.get_double("Amplitude max");
    omegas         = curve_values(prm, "Omegas");
    amplitudes     = curve_values(prm, "Amplitudes");
    prm.leave_subsection();
    require(omegas.empty() || force_range() > 0, "Forcing/Amplitude max",
            "> 0, or Forcing/Amplitudes set, when Forcing/Omegas is set (the force-response curves' range)", "0");
  }

  double ForcingParameters::force_range() const
  {
    if (amplitude_max > 0 || amplitudes.empty())
      return amplitude_max;
    return *std::max_element(amplitudes.begin(), amplitudes.end());
  }
} // namespace nsm
