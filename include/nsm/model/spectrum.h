// Eigenpairs of K phi = w^2 M phi for the clamped-free and clamped-clamped
// bar, from banded LAPACK (the 1D FE matrices have bandwidth p after
// Cuthill-McKee ordering).
#pragma once

#include <nsm/model/banded_pencil.h>
#include <nsm/model/discretisation.h>
#include <nsm/model/near_modes.h>

#include <vector>

namespace nsm
{
  /// The lowest `count` eigenvalues (count = 0: all), from LAPACK dsbgvx in
  /// the form accurate for each (method.md), and with them, if asked (for
  /// the clamped-free bar), the residues phi_j(L)^2 from the clamped-free and
  /// clamped-clamped spectra and gamma(0): no eigenvector is computed.
  ModalData compute_spectrum(const Discretisation &discretisation,
                             EndCondition          ends,
                             unsigned int          count,
                             bool                  with_contact_residues);

  /// Eigenvalues w_j^2 <= omega_max^2 (unrefined, from the stiffness-factored form, accurate for the low modes: used to count poles).
  std::vector<double> eigenvalues_below(const BandedPencil &pencil, double omega_max);
} // namespace nsm
