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
    , reference_(std::make_unique<Discretisation>(model, model.fe().degree + judge_degree_step, 1))
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
    std::vector<double>            changes;
    const std::vector<std::size_t> sample = spread_main_points(backbone, space_samples);
    if (sample.empty())
      return changes;
    HarmonicBalance model(branch_.harmonic_balance, branch_.contact, *receptance_);
    SameMotionSolve solve(model, branch_.harmonic_balance);
    for (const std::size_t i : sample)
      changes.push_back(solve.energy_change(backbone.points[i], backbone.points[i].x));
    return changes;
  }

  SpaceVerdict space_verdict(const BandAgreement &band, const std::vector<double> &energy_changes,
                             const double harmonics_estimate, const Discretisation &model)
  {
    // A point the judge does not find again from its own unknowns (no
    // contact motion, or one of another contact) has moved to another
    // motion: it is counted apart, not as a change of the same motion.
    std::vector<double> found;
    for (const double c : energy_changes)
      if (std::isfinite(c))
        found.push_back(c);
    std::sort(found.begin(), found.end());
    const std::size_t lost  = energy_changes.size() - found.size();
    const std::string ours  = "FE_Q(" + std::to_string(model.fe().degree) + ") x " + std::to_string(model.n_cells());
    const std::string judge = "FE_Q(" + std::to_string(model.fe().degree + judge_degree_step) + ") with every cell "
                              "halved (" + std::to_string(2 * model.n_cells()) + " cells)";
    std::ostringstream s;
    s.precision(2);
    s << "spatial error (" << ours << " against " << judge
      << "): eigenfrequencies up to M times the branch's highest Omega = " << significant(band.top, 4) << " ("
      << counted(band.modes, "mode") << ") agree to " << band.error;
    if (energy_changes.empty())
      return {s.str(), ""};
    s << "; the " << found.size() << " of " << energy_changes.size() << " main points found again on the same motion";
    if (!found.empty())
      s << " changed their energy by a median " << 100 * found[found.size() / 2] << " %";
    if (lost > 0)
      s << " (" << lost << " moved to another motion, not counted)";
    const bool by_energy = 2 * found.size() > energy_changes.size();
    if (!by_energy)
      s << "; with most of them moved, the eigenfrequencies alone judge the mesh";
    SpaceVerdict verdict{s.str(), ""};
    if (!std::isfinite(harmonics_estimate))
      return verdict;
    // The mesh limits the run where the judge moves either the main points'
    // energy (a median over most of them found again) or the band's
    // eigenfrequencies more than the truncation: measured against FE_Q(10) x
    // 40 at the same M on the seed bar, each such mesh's main branch was off
    // by more than its estimate, and each other one by less (method.md, "A
    // run's own accuracy").
    const double energy    = by_energy ? found[found.size() / 2] : 0;
    if (energy <= harmonics_estimate && band.error <= harmonics_estimate)
      return verdict;
    std::ostringstream w;
    w.precision(2);
    w << "the mesh limits the accuracy: " << judge << " ";
    if (energy > harmonics_estimate)
      w << "moves the main points' energy by a median " << 100 * energy << " %";
    else
      w << "moves the eigenfrequencies up to M times the branch's highest Omega by up to " << 100 * band.error << " %";
    w << ", more than the harmonic balance's estimated " << 100 * harmonics_estimate
      << " %: raise Discretisation/Cells or Degree (now " << ours << ")";
    verdict.warning = w.str();
    return verdict;
  }
} // namespace nsm
