#include <nsm/scene/discretisation_parameters.h>
#include <nsm/scene/parameter_limits.h>
#include <nsm/scene/scene_entries.h>

#include <deal.II/base/parameter_handler.h>

#include <cmath>
#include <string>

namespace nsm
{
  namespace
  {
    using namespace scene_entries;

    const Options<Refinement> refinements = {{"none", Refinement::none},
                                             {"graded", Refinement::graded},
                                             {"adaptive", Refinement::adaptive}};
    const Options<ContactMass> contact_masses = {{"consistent", ContactMass::consistent},
                                                 {"redistributed", ContactMass::redistributed}};

    /// Smallest cell of a graded mesh relative to L (make_mesh's sizes).
    double graded_smallest_cell(const DiscretisationParameters &d, const unsigned int layers)
    {
      double total = d.cells - layers;
      for (unsigned int i = 1; i <= layers; ++i)
        total += std::pow(d.graded_ratio, i);
      return std::pow(d.graded_ratio, layers) / total;
    }

    void require_graded_cells_above_roundoff(const DiscretisationParameters &d)
    {
      if (graded_smallest_cell(d, d.graded_layers) >= d.smallest_cell())
        return;
      unsigned int allowed = d.graded_layers;
      while (allowed > 0 && graded_smallest_cell(d, allowed) < d.smallest_cell())
        --allowed;
      require(false,
              "Discretisation/Graded/Layers",
              "at most " + std::to_string(allowed) + " with Ratio = " +
                format_value(d.graded_ratio) + " and Cells = " + std::to_string(d.cells) +
                " (more make cells smaller than " + format_value(d.smallest_cell()) +
                " L, where the round-off floor eps p^2 L / h_min exceeds "
                "Discretisation/Round-off limit = " + format_value(d.roundoff_limit) + ")",
              std::to_string(d.graded_layers));
    }
    /// Graded refinement with no layer, or with cells that do not shrink, is
    /// the uniform mesh: a scene that asks for grading gets it or an error.
    void require_grading_refines(const DiscretisationParameters &d)
    {
      if (d.refinement != Refinement::graded)
        return;
      require(d.graded_layers >= 1,
              "Discretisation/Graded/Layers",
              "an integer in [1, Cells] = [1, " + std::to_string(d.cells) +
                "] with Refinement = graded (0 layers refine nothing)",
              std::to_string(d.graded_layers));
      require(d.graded_ratio < 1,
              "Discretisation/Graded/Ratio",
              "a number in [1e-06, 1) with Refinement = graded (1 refines nothing)",
              format_value(d.graded_ratio));
    }
  } // namespace

  void DiscretisationParameters::declare(ParameterHandler &prm)
  {
    const DiscretisationParameters d;
    prm.enter_subsection("Discretisation");
    prm.declare_entry("Degree", text(d.degree), Patterns::Integer(1, 20), "FE_Q degree p.");
    prm.declare_entry("Cells",
                      text(d.cells),
                      Patterns::Integer(0, 1000000),
                      "Initial cells; 0 = the fewest, doubling from max(1, Graded/Layers), whose "
                      "eigenfrequencies up to M Omega max agree with twice the cells' to 1e-5 (not with "
                      "Refinement = adaptive, nor in a study).");
    prm.declare_entry("Quadrature points",
                      text(d.quadrature_points),
                      Patterns::Integer(0, 64),
                      "Gauss points per cell; 0 = degree + 2 (exact for a cross-section "
                      "polynomial of degree <= 3); otherwise at least degree + 1, which "
                      "integrates the mass matrix of a constant section exactly.");
    prm.declare_entry("Round-off limit",
                      text(d.roundoff_limit),
                      Patterns::Double(1e-12, 1e-6),
                      "Largest accepted round-off floor eps p^2 L / h_min of the stiffness "
                      "matrix: the relative error that rounding alone puts on gamma and the "
                      "spectrum when the smallest cell is h_min. Graded meshes with smaller "
                      "cells are rejected; adaptive refinement stops before it makes them. "
                      "Above 1e-6 the LU of K - w^2 M itself breaks down.");
    prm.declare_entry("Refinement",
                      name_of(d.refinement, refinements),
                      selection(refinements),
                      "Mesh refinement towards the contact end x = L.");
    prm.declare_entry("Contact mass",
                      name_of(d.contact_mass, contact_masses),
                      selection(contact_masses),
                      "consistent: the consistent mass matrix; redistributed: the contact DoF's "
                      "mass moved to the DoFs it couples, so that it has no inertia. That is the "
                      "model of Output/Verify in time and Refine in time: harmonic balance then "
                      "approaches their periodic orbits as Harmonics grows, and its error against "
                      "them is truncation alone. The clamped-free problem has one mode fewer; a "
                      "modal receptance needs every mode (Receptance/Modes = 0).");
    prm.enter_subsection("Graded");
    prm.declare_entry("Ratio",
                      text(d.graded_ratio),
                      Patterns::Double(1e-6, 1),
                      "Size ratio of neighbouring cells in the graded layer; below 1 with Refinement = graded.");
    prm.declare_entry("Layers",
                      text(d.graded_layers),
                      Patterns::Integer(0, 1000000),
                      "Cells at the contact end that shrink geometrically; at least 1 with Refinement = "
                      "graded, at most Cells, and the smallest within the Round-off limit.");
    prm.leave_subsection();
    prm.enter_subsection("Adaptive");
    prm.declare_entry("Steps", text(d.adaptive_steps), Patterns::Integer(0, 50), "Refinement steps at most.");
    prm.declare_entry("Tolerance",
                      text(d.adaptive_tolerance),
                      Patterns::Double(1e-15, 0.1),
                      "Target relative error of gamma over the band.");
    prm.declare_entry("Refine fraction",
                      text(d.adaptive_fraction),
                      Patterns::Double(1e-6, 1),
                      "Fraction of cells refined per step (at least one cell).");
    prm.declare_entry("Band max omega",
                      text(d.adaptive_band_max),
                      Patterns::Double(0, frequency_limit),
                      "Upper end of the frequency band of the estimator; 0 = the largest "
                      "frequency the scene needs.");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  void DiscretisationParameters::check_cells() const
  {
    require(graded_layers <= cells,
            "Discretisation/Graded/Layers",
            "an integer in [0, Cells] = [0, " + std::to_string(cells) + "]",
            std::to_string(graded_layers));
    require_grading_refines(*this);
    require_graded_cells_above_roundoff(*this);
  }

  void DiscretisationParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretisation");
    degree            = get_unsigned(prm, "Degree");
    cells             = get_unsigned(prm, "Cells");
    quadrature_points = get_unsigned(prm, "Quadrature points");
    require(quadrature_points == 0 || quadrature_points >= degree + 1,
            "Discretisation/Quadrature points",
            "0 (= Degree + 2) or an integer in [Degree + 1, 64] = [" + std::to_string(degree + 1) +
              ", 64]: fewer make the mass matrix singular",
            std::to_string(quadrature_points));
    roundoff_limit = prm.get_double("Round-off limit");
    refinement     = selected(prm.get("Refinement"), refinements);
    contact_mass   = selected(prm.get("Contact mass"), contact_masses);
    prm.enter_subsection("Graded");
    graded_ratio  = prm.get_double("Ratio");
    graded_layers = get_unsigned(prm, "Layers");
    if (cells != 0)
      check_cells();
    prm.leave_subsection();
    prm.enter_subsection("Adaptive");
    adaptive_steps     = get_unsigned(prm, "Steps");
    adaptive_tolerance = prm.get_double("Tolerance");
    adaptive_fraction  = prm.get_double("Refine fraction");
    adaptive_band_max  = prm.get_double("Band max omega");
    prm.leave_subsection();
    prm.leave_subsection();
  }

  double DiscretisationParameters::smallest_cell() const
  {
    return std::numeric_limits<double>::epsilon() * degree * degree / roundoff_limit;
  }
} // namespace nsm
