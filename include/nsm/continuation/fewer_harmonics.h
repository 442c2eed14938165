// The same branch traced with half the harmonics, on first use: where a leap
// (leap.h) or a gap search (gap_filling.h) finds no landing from its own
// guesses, that branch's points lie near solutions. compute_backbone makes one
// for the branch it traces and passes it to the branch's context; tracing it
// makes the next one down (M / 4) the same way, again only on first use, and
// the backbone records each branch traced (Backbone::fewer_harmonics_traced).
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/continuation/branch_parameters.h>

#include <memory>
#include <utility>
#include <vector>

namespace nsm
{
  class FewerHarmonicsBranch
  {
  public:
    /// The branch of `params` with half its harmonics, on the receptance of
    /// `hb`, which must outlive this object.
    FewerHarmonicsBranch(const HarmonicBalance &hb, const BranchParameters &params,
                         std::vector<InternalResonance> resonances);
    ~FewerHarmonicsBranch();

    /// The branch, traced now if not yet (never with its gaps filled); null
    /// below 2 harmonics.
    const Backbone *get();

    /// (harmonics, points) of this branch and of those it traced in turn, if
    /// it was traced; empty otherwise.
    std::vector<std::pair<unsigned int, std::size_t>> traced() const;

    /// Its Newton solves (none unless traced).
    NewtonCost newton_cost() const;

  private:
    const HarmonicBalance               &hb_;
    BranchParameters                     params_; ///< with half the harmonics
    std::vector<InternalResonance>       resonances_;
    std::unique_ptr<Backbone>            branch_;
  };
} // namespace nsm
