// Whether a mesh resolves the band the harmonic balance evaluates, [0, M Omega
// max]: its clamped-free eigenfrequencies there against a finer mesh's, and
// the number of cells chosen for the band (Discretisation/Cells = 0;
// doc/method.md, "The band check").
#pragma once

#include <nsm/model/bar_model.h>
#include <nsm/model/discretisation.h>

#include <string>
#include <vector>

namespace nsm
{
  struct Scene;

  /// The eigenfrequencies up to which Cells = 0 resolves the band: the
  /// chosen mesh's agree with twice its cells' to this. In the band check's
  /// measurements halving the cells moved the main points' energy by 1 to 43
  /// times the eigenfrequencies' difference (doc/method.md, "The band
  /// check"), so 1e-5 keeps the mesh's share below 0.05 %, a seventh of the
  /// smallest median truncation error measured (0.36 %, the seed bar's model at
  /// M = 80).
  constexpr double band_tolerance = 1e-5;

  /// The band check's judge (verification/space_estimate.h) is the model's
  /// mesh with its cells halved and its degree raised by this, so that it is
  /// converged where a coarse mesh is not (a mesh of FE_Q(p) with its cells
  /// halved alone was 1.1 to 2.5 % from converged for coarse p = 1 and 2
  /// meshes, as far as the meshes it judged). The memory estimate counts it.
  constexpr unsigned int judge_degree_step = 1;

  struct BandAgreement
  {
    double       top   = 0; ///< the band's upper end
    unsigned int modes = 0; ///< the finer mesh's clamped-free modes up to top
    double       error = 0; ///< the largest |w_j / w_j,fine - 1| among them
  };

  /// The coarse mesh's eigenfrequencies against the fine one's up to `top`.
  /// A coarse mesh's lie above: its counterparts are sought up to twice top,
  /// and a mode with none there counts as 2 top / w_j,fine - 1 (a lower bound).
  BandAgreement band_agreement(const Discretisation &coarse, const Discretisation &fine, double top);

  /// How many clamped-free modes the continuum bar has below `top`:
  /// w_j ~ (j - 1/2) pi / tau, tau = L sqrt(rho / E) the wave's travel time
  /// (asymptotically exact in j for a smooth section of one material).
  double continuum_modes_below(const BarModel &bar, double top);

  /// Discretisation/Cells = 0: the fewest cells, doubling from max(1, Graded/
  /// Layers), whose eigenfrequencies up to the scene's receptance band agree
  /// with twice as many cells' to band_tolerance (an automatic Omega max is
  /// read off each candidate; a mesh with fewer than Mode + 1 modes is
  /// skipped). Throws InputError if the scene needs no band or one with more
  /// modes than the largest mesh has degrees of freedom (before building
  /// it), NumericalError if no mesh up to the Cells bound reaches it, and
  /// StopRequested at a stop signal, between candidates. Prints a progress
  /// line per candidate every Output/Progress every seconds.
  struct BandCells
  {
    unsigned int              cells = 0;
    BandAgreement             agreement;
    std::vector<unsigned int> tried;
  };
  BandCells cells_for_band(const BarModel &bar, const Scene &scene);

  /// "Discretisation/Cells = 0: ..." for the run summary.
  std::string describe(const BandCells &choice, unsigned int degree);
} // namespace nsm
