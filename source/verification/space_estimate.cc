#include <nsm/base/text.h>
#include <nsm/model/band_cells.h>
#include <nsm/verification/harmonics_estimate.h>
#include <nsm/verification/space_estimate.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// Main points solved again on the reference: evenly spread, enough for
    /// a median that one point near a tongue (whose resonance the reference
    /// moves) does not decide, few enough to cost under a tenth of the run.
    constexpr unsigned int space_samples = 15;
  } // namespace

  SpaceReference::SpaceReference(const Discretisation &model, const ReceptanceParameters &receptance,
                                 const BranchParameters &branch)
    : branch_(branch)
    , reference_(std::make_unique<Discretisation>(model, model.fe().degree, 1))
    , receptance_(std::make_unique<Receptance>(*reference_, receptance,
                                               branch.harmonic_balance.harmonics * branch.continuation.omega_max))
  {}

  BandAgreement SpaceReference::band(const Discretisation &model) const
  {
    return band(model, branch_.harmonic_balance.harmonics * branch_.continuation.omega_max);
  }

  BandAgreement SpaceReference::band(const Discretisation &model, const double top) const
  {
    return band_agreement(model, *reference_, top);
  }

  std::vector<double> SpaceReference::energy_changes(const Backbone &backbone) const
  {
    std::vector<const BackbonePoint *> main;
    for (const BackbonePoint &p : backbone.points)
      if (p.branch == Branch::main)
        main.push_back(&p);
    std::vector<double> changes;
    if (main.empty())
      return changes;
    HarmonicBalance    model(branch_.harmonic_balance, branch_.contact, *receptance_);
    SameMotionSolve    solve(model, branch_.harmonic_balance);
    const std::size_t  count = std::min<std::size_t>(space_samples, main.size());
    for (std::size_t i = 0; i < count; ++i)
      {
        const BackbonePoint &p = *main[count == 1 ? 0 : i * (main.size() - 1) / (count - 1)];
        changes.push_back(solve.energy_change(p, p.x));
      }
    return changes;
  }

  SpaceVerdict space_verdict(const BandAgreement &band, const std::vector<double> &energy_changes,
                             const double harmonics_estimate, const Discretisation &model)
  {
    // A point the finer mesh does not find again from its own unknowns has
    // moved beyond Newton's reach: it counts as beyond any bound.
    std::vector<double> changes = energy_changes;
    for (double &c : changes)
      if (!std::isfinite(c))
        c = std::numeric_limits<double>::infinity();
    std::sort(changes.begin(), changes.end());
    const auto lost = std::count(changes.begin(), changes.end(), std::numeric_limits<double>::infinity());
    const std::string ours = "FE_Q(" + std::to_string(model.fe().degree) + ") x " + std::to_string(model.n_cells());
    std::ostringstream s;
    s.precision(2);
    s << "spatial error (" << ours << " against every cell halved, " << 2 * model.n_cells()
      << " cells): eigenfrequencies up to M times the branch's highest Omega = " << significant(band.top, 4) << " (" << band.modes
      << " modes) agree to " << band.error;
    if (changes.empty())
      return {s.str(), ""};
    const double median = changes[changes.size() / 2];
    s << "; main points' energy changed by a median ";
    if (std::isfinite(median))
      s << 100 * median << " %";
    else
      s << "beyond reach";
    s << " (" << changes.size() - lost << " of " << changes.size() << " found again)";
    SpaceVerdict verdict{s.str(), ""};
    if (std::isfinite(harmonics_estimate) && median > harmonics_estimate)
      {
        std::ostringstream w;
        w.precision(2);
        w << "the mesh limits the accuracy: every cell halved (" << 2 * model.n_cells()
          << " cells) moves the main points' energy by a median ";
        if (std::isfinite(median))
          w << 100 * median << " %";
        else
          w << "beyond reach (more than half not found again)";
        w << ", more than the harmonic balance's estimated " << 100 * harmonics_estimate
          << " %: raise Discretisation/Cells or Degree (now " << ours << ")";
        verdict.warning = w.str();
      }
    return verdict;
  }
} // namespace nsm
