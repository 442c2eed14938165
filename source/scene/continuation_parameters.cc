#include <nsm/scene/continuation_parameters.h>
#include <nsm/scene/parameter_limits.h>
#include <nsm/scene/scene_entries.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace nsm
{
  namespace
  {
    using namespace scene_entries;

    const Options<ContinuationMethod> continuation_methods = {
      {"sequential", ContinuationMethod::sequential},
      {"arclength", ContinuationMethod::arclength}};
  } // namespace

  void ContinuationParameters::declare(ParameterHandler &prm)
  {
    const ContinuationParameters d;
    prm.enter_subsection("Continuation");
    prm.declare_entry("Method",
                      name_of(d.method, continuation_methods),
                      selection(continuation_methods),
                      "sequential: steps in Omega (the paper); arclength: LOCA pseudo-arclength.");
    prm.declare_entry("Mode",
                      text(d.mode),
                      Patterns::Integer(1, 1000000),
                      "Clamped-free mode j whose grazing starts the branch; at most the number "
                      "of modes of the mesh.");
    prm.declare_entry("Omega min", text(d.omega_min), Patterns::Double(0, frequency_limit), "Lower end of the Omega range.");
    prm.declare_entry("Omega max",
                      text(d.omega_max),
                      Patterns::Double(0, frequency_limit),
                      "Upper end of the Omega range, > Omega min; harmonics up to Harmonics x "
                      "Omega max are resolved. 0: from the FE model's spectrum, w_j + 0.8 (w_b - "
                      "w_j), with w_j the clamped-free and w_b = 2 w_j w_h / (w_j + w_h) the "
                      "bilinear estimate of the branch's infinite-energy limit (w_h the bar held at the "
                      "wall: clamped-clamped, or on a compliant wall's spring); "
                      "the summary says the value.");
    prm.declare_entry("Energy max",
                      text(d.energy_max),
                      Patterns::Double(0, 1e300),
                      "Points above it are not kept: the branch is climbing a resonance tongue, "
                      "and the run leaps past it to a new segment; above the energy at grazing. "
                      "0: Energy max over grazing times the grazing energy E_g (grazing.csv).");
    prm.declare_entry("Energy max over grazing",
                      text(d.energy_max_over_grazing),
                      Patterns::Double(1, 1e300),
                      "Where Energy max = 0, Energy max is this many times the grazing energy "
                      "E_g of Mode, the energy of its linear mode with u(L) = g0.");
    prm.declare_entry("Initial step",
                      text(d.initial_step),
                      Patterns::Double(1e-15, frequency_limit),
                      "First step in Omega (arclength: in arclength, unscaled) and first leap "
                      "distance.");
    prm.declare_entry("Min step",
                      text(d.min_step),
                      Patterns::Double(1e-15, frequency_limit),
                      "Smallest step before a fold is declared; <= Initial step.");
    prm.declare_entry("Max step",
                      text(d.max_step),
                      Patterns::Double(1e-15, frequency_limit),
                      "Largest step in Omega (arclength: in arclength, unscaled, so also in "
                      "Omega), >= Initial step; never more than a tenth of the range covered.");
    prm.declare_entry("Max steps", text(d.max_steps), Patterns::Integer(1, 1000000), "Most backbone points.");
    prm.declare_entry("Grazing offset",
                      text(d.grazing_offset),
                      Patterns::Double(1e-12, 1e-2),
                      "Relative distance of the first try from grazing, W = w_j (1 +- offset), "
                      "doubled until Newton converges.");
    prm.declare_entry("Tongue share",
                      text(d.tongue_share),
                      Patterns::Double(1e-4, 1),
                      "A point is labelled a tongue point if its energy exceeds the least energy "
                      "written at or beyond its Omega (in the direction of continuation) by more "
                      "than this share, or if it lies behind an earlier main point of its segment in "
                      "Omega (the back of a fold); otherwise it is on the main branch.");
    prm.declare_entry("Main contact drop",
                      text(d.main_contact_drop),
                      Patterns::Double(1e-4, 1),
                      "The main branch is the family connected to grazing, whose contact lasts "
                      "longer as it hardens: a point whose contact fraction lies more than this "
                      "below the most contact of that family before it in Omega belongs to "
                      "another family (labelled other), whatever its energy. Above the truncated "
                      "series' own error in the contact fraction (0.04 on the uniform bar at "
                      "M = 20), below the falls of leaps onto other families (0.15 to 0.28).");
    prm.declare_entry("Tongue energy ratio",
                      text(d.tongue_energy_ratio),
                      Patterns::Double(1, 1e6),
                      "Arclength follows a resonance tongue until its energy reaches this many "
                      "times the energy where the segment first turned back (a fold), then "
                      "leaps to the main branch beyond the tongue.");
    prm.declare_entry("Max contact change",
                      text(d.max_contact_change),
                      Patterns::Double(1e-6, 1),
                      "Largest change of the contact fraction from one point of a segment to "
                      "the next; a larger one is a jump to another branch, and the step is "
                      "shortened.");
    prm.declare_entry("Max solution change",
                      text(d.max_solution_change),
                      Patterns::Double(1e-3, 10),
                      "Largest change of the HB unknowns from one point of a segment to the "
                      "next, relative to their norm; a larger one is a jump to another branch, "
                      "and the step is shortened.");
    prm.declare_entry("Leap energy ratio",
                      text(d.leap_energy_ratio),
                      Patterns::Double(1.001, 1e6),
                      "A leap lands only below this many times the energy before the fold (above "
                      "it, on a tongue's flank) and above the least energy written within reach "
                      "behind the front divided by it.");
    prm.declare_entry("Search reach",
                      text(d.search_reach),
                      Patterns::Double(1e-4, 0.5),
                      "How far, relative to Omega, the start searches from grazing and a leap "
                      "searches beyond the front for a converged point.");
    prm.declare_entry("Leap from fewer harmonics",
                      d.leap_from_fewer_harmonics ? "true" : "false",
                      Patterns::Bool(),
                      "Where a leap finds no landing from its own guesses, it tries the main "
                      "points within reach of the same branch traced once with half the "
                      "harmonics, their higher harmonics zero, then its main points beyond "
                      "reach rather than lose the branch. Near dense internal resonances "
                      "(the seed bar at M = 160) Newton converges from nothing else.");
    prm.declare_entry("Fill gaps wider than",
                      text(d.fill_gaps_wider_than),
                      Patterns::Double(0, 1),
                      "Once the continuation ends (at the range's end or where the branch is "
                      "lost), every gap between main points wider than this (in Omega) is "
                      "searched once: Newton from the mode predicted along its trend at Omegas "
                      "an eighth of this apart, then from the points inside it of the branch traced "
                      "with half the harmonics, each start solved once in the run; a main solution "
                      "found starts a segment of sequential steps up to the gap's far side. Without "
                      "one, the branch is traced back from the far side. The Result block names "
                      "every gap left, with what the search found there and its Newton solves. 0: "
                      "no search.");
    prm.leave_subsection();
  }

  void ContinuationParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Continuation");
    method    = selected(prm.get("Method"), continuation_methods);
    mode      = get_unsigned(prm, "Mode");
    omega_min = prm.get_double("Omega min");
    omega_max = prm.get_double("Omega max");
    require(omega_max == 0 || omega_max > omega_min,
            "Continuation/Omega max",
            "> Continuation/Omega min = " + format_value(omega_min) + " (the range runs from Omega min up to Omega max), or 0 (from the spectrum)",
            format_value(omega_max));
    energy_max   = prm.get_double("Energy max");
    energy_max_over_grazing = prm.get_double("Energy max over grazing");
    initial_step = prm.get_double("Initial step");
    min_step     = prm.get_double("Min step");
    require(min_step <= initial_step,
            "Continuation/Min step",
            "<= Initial step = " + format_value(initial_step),
            format_value(min_step));
    max_step = prm.get_double("Max step");
    require(max_step >= initial_step,
            "Continuation/Max step",
            ">= Initial step = " + format_value(initial_step),
            format_value(max_step));
    max_steps      = get_unsigned(prm, "Max steps");
    grazing_offset = prm.get_double("Grazing offset");
    tongue_share   = prm.get_double("Tongue share");
    main_contact_drop   = prm.get_double("Main contact drop");
    tongue_energy_ratio = prm.get_double("Tongue energy ratio");
    max_contact_change  = prm.get_double("Max contact change");
    max_solution_change = prm.get_double("Max solution change");
    leap_energy_ratio   = prm.get_double("Leap energy ratio");
    search_reach        = prm.get_double("Search reach");
    leap_from_fewer_harmonics = prm.get_bool("Leap from fewer harmonics");
    fill_gaps_wider_than      = prm.get_double("Fill gaps wider than");
    require(grazing_offset < search_reach,
            "Continuation/Grazing offset",
            "< Search reach = " + format_value(search_reach),
            format_value(grazing_offset));
    prm.leave_subsection();
  }
} // namespace nsm
