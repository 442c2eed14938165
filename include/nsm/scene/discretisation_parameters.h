// The Discretisation subsection: FE_Q(p), the mesh and its refinement
// (model/discretisation.h reads it). It declares and parses its own entries;
// Scene (scene.h) composes the subsections.
#pragma once

namespace dealii
{
  class ParameterHandler;
} // namespace dealii

namespace nsm
{
  enum class Refinement
  {
    none,
    graded,
    adaptive
  };

  /// Where the mass of the contact DoF goes.
  enum class ContactMass
  {
    consistent,   ///< the consistent mass matrix as assembled
    redistributed ///< moved to the DoFs it couples: no inertia at the contact DoF
  };

  struct DiscretisationParameters
  {
    unsigned int degree             = 1;
    unsigned int cells              = 4000; ///< 0: chosen for the band (model/band_cells.h)
    unsigned int quadrature_points  = 0; ///< 0: degree + 2
    double       roundoff_limit     = 1e-7;
    Refinement   refinement         = Refinement::none;
    ContactMass  contact_mass       = ContactMass::consistent;
    double       graded_ratio       = 0.8;
    unsigned int graded_layers      = 0;
    unsigned int adaptive_steps     = 10;
    double       adaptive_tolerance = 1e-8;
    double       adaptive_fraction  = 0.3;
    double       adaptive_band_max  = 0.0; ///< 0: derived from the scene

    /// Smallest cell size, relative to L, that keeps the round-off floor
    /// eps p^2 L / h_min of the stiffness matrix within `roundoff_limit`.
    double smallest_cell() const;

    /// The checks that need Cells (Graded/Layers within it, the round-off
    /// floor of the graded layer): at parsing, or once Cells = 0 is chosen
    /// (model/band_cells.h).
    void check_cells() const;

    static void declare(dealii::ParameterHandler &prm);
    void        parse(dealii::ParameterHandler &prm);
  };
} // namespace nsm
