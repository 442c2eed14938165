// A mass matrix without inertia at the contact DoF. With a mass at the
// contact DoF, the bar's end is a point mass striking a rigid wall, whose
// impact needs a restitution law; without it the wall's force is a bounded
// function of time and the motion is the one the Signorini law defines. The
// model of the time verification and of the periodic orbits, and of harmonic
// balance with Discretisation/Contact mass = redistributed.
#pragma once

#include <deal.II/lac/sparse_matrix.h>

namespace nsm
{
  /// Removes the contact DoF's row and column of `mass` and adds the total
  /// mass 1^T M 1 they carried to the diagonal of the DoFs they coupled, in
  /// proportion to the coupling. A matrix already without them is unchanged.
  void redistribute_contact_mass(dealii::SparseMatrix<double> &mass, unsigned int contact);
} // namespace nsm
