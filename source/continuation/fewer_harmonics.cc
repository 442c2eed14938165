#include <nsm/base/interruption.h>
#include <nsm/continuation/continuation.h>
#include <nsm/continuation/fewer_harmonics.h>

namespace nsm
{
  namespace
  {
    BranchParameters with_half_the_harmonics(BranchParameters fewer)
    {
      // The run's own Newton iterations (Max iterations = 0 would give the
      // M / 2 run fewer): at M = 320 the seed bar's M / 2 branch with 12 lets
      // the run be lost at 2.19991, with 20 it carries it to 2.2.
      fewer.harmonic_balance.max_iterations = fewer.harmonic_balance.iterations();
      fewer.harmonic_balance.harmonics /= 2;
      // Unfilled, so that a run's leaps do not depend on whether it fills its gaps.
      fewer.continuation.fill_gaps_wider_than = 0;
      return fewer;
    }
  } // namespace

  FewerHarmonicsBranch::FewerHarmonicsBranch(const HarmonicBalance &hb, const BranchParameters &params,
                                             std::vector<InternalResonance> resonances)
    : hb_(hb)
    , params_(with_half_the_harmonics(params))
    , resonances_(std::move(resonances))
  {}

  FewerHarmonicsBranch::~FewerHarmonicsBranch() = default;

  const Backbone *FewerHarmonicsBranch::get()
  {
    if (params_.harmonic_balance.harmonics < 1)
      return nullptr;
    if (!branch_)
      {
        HarmonicBalance          model(params_.harmonic_balance, params_.contact, hb_.receptance());
        const PointStopsDeferred whole;
        branch_ = std::make_unique<Backbone>(compute_backbone(model, params_, resonances_));
      }
    return branch_.get();
  }

  std::vector<std::pair<unsigned int, std::size_t>> FewerHarmonicsBranch::traced() const
  {
    if (!branch_)
      return {};
    std::vector<std::pair<unsigned int, std::size_t>> list{{params_.harmonic_balance.harmonics, branch_->points.size()}};
    list.insert(list.end(), branch_->fewer_harmonics_traced.begin(), branch_->fewer_harmonics_traced.end());
    return list;
  }

  NewtonCost FewerHarmonicsBranch::newton_cost() const { return branch_ ? branch_->newton_cost : NewtonCost{}; }
} // namespace nsm
