// The spatial model's error over the band the harmonic balance evaluates,
// [0, M Omega max]: the FE model against the same degree on its mesh with
// every cell halved (doc/method.md, "The band check"). That model is made
// before the harmonic balance; after it, its eigenfrequencies in the band are
// compared, and the energies of sampled main points solved again on it, in
// the units of the harmonic balance's own estimate (harmonics_estimate.h).
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/continuation/branch_parameters.h>
#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/model/band_cells.h>
#include <nsm/model/discretisation.h>
#include <nsm/model/receptance.h>
#include <nsm/scene/receptance_parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace nsm
{
  class SpaceReference
  {
  public:
    /// FE_Q(p) on the model's mesh with every cell halved, and its
    /// receptance up to the band M Omega max of `branch`.
    SpaceReference(const Discretisation &model, const ReceptanceParameters &receptance,
                   const BranchParameters &branch);

    /// The model's eigenfrequencies up to M Omega max against the reference's.
    BandAgreement band(const Discretisation &model) const;

    /// The same up to `top` (the band the backbone used: M times its highest
    /// Omega, which an Omega max far beyond the branch's end exceeds by any
    /// factor).
    BandAgreement band(const Discretisation &model, double top) const;

    /// Per sampled main point (space_samples, evenly spread over the main
    /// points), |E_ref / E - 1|: E_ref solved at its Omega on the reference
    /// from its own unknowns; NaN where that Newton finds no contact motion
    /// or lands on another motion.
    std::vector<double> energy_changes(const Backbone &backbone) const;

  private:
    const BranchParameters          branch_;
    std::unique_ptr<Discretisation> reference_;
    std::unique_ptr<Receptance>     receptance_;
  };

  /// "spatial error ..." for the run summary, and the warning naming
  /// Discretisation where the median energy change exceeds the harmonic
  /// balance's median estimate (empty otherwise).
  struct SpaceVerdict
  {
    std::string summary, warning;
  };
  SpaceVerdict space_verdict(const BandAgreement &band, const std::vector<double> &energy_changes,
                             double harmonics_estimate, const Discretisation &model);
} // namespace nsm
