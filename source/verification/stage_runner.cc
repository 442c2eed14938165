#include <nsm/base/progress.h>
#include <nsm/model/adaptive_refinement.h>
#include <nsm/verification/stage_runner.h>

namespace nsm
{
  std::vector<std::string> StageRunner::mesh(const BarModel &bar, const DiscretisationParameters &parameters,
                                             const std::function<double(const Discretisation &)> &band,
                                             const double progress_every)
  {
    // What was built on an earlier mesh goes with it.
    hb_.reset();
    receptance_.reset();
    backbone_ = Backbone();
    timed("mesh", [&] { discretisation_ = std::make_unique<Discretisation>(bar, parameters); });
    if (parameters.refinement != Refinement::adaptive)
      return {};
    return timed("refinement", [&] {
      Progress progress("adaptive refinement", progress_every);
      return refine_adaptively(*discretisation_, parameters, band(*discretisation_), &progress);
    });
  }

  void StageRunner::set_up_receptance(const ReceptanceParameters &parameters, const double band)
  {
    timed("receptance set-up",
          [&] { receptance_ = std::make_unique<Receptance>(*discretisation_, parameters, band); });
  }

  void StageRunner::harmonic_balance(const HarmonicBalanceParameters &parameters, const ContactParameters &contact,
                                     const BranchParameters &branch, const Resume &resume)
  {
    timed("harmonic balance", [&] {
      hb_         = std::make_unique<HarmonicBalance>(parameters, contact, *receptance_);
      resonances_ = internal_resonances(*receptance_, branch);
      std::optional<ContinuationCheckpoint> resumed;
      if (resume)
        resumed = resume(*hb_);
      backbone_ = compute_backbone(*hb_, branch, resonances_, resumed ? &*resumed : nullptr);
    });
  }
} // namespace nsm
