// The stages a run of a scene and a study's row share, in their order: the
// mesh (and its adaptive refinement), the receptance of the contact node, and
// the harmonic balance with its continuation. Each is timed on the runner's
// StageClock under its name, beside the stages the caller adds with timed():
// a run (app/pipeline.cc) adds its checks, tables and outputs, a study's row
// (study/study_measures.cc) its error measures.
#pragma once

#include <nsm/base/stage_clock.h>
#include <nsm/continuation/backbone.h>
#include <nsm/continuation/branch_parameters.h>
#include <nsm/continuation/checkpoint.h>
#include <nsm/continuation/continuation.h>
#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/model/bar_model.h>
#include <nsm/model/discretisation.h>
#include <nsm/model/receptance.h>
#include <nsm/scene/contact_parameters.h>
#include <nsm/scene/discretisation_parameters.h>
#include <nsm/scene/harmonic_balance_parameters.h>
#include <nsm/scene/receptance_parameters.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace nsm
{
  class StageRunner
  {
  public:
    /// Runs `work` as the stage `name` on the runner's clock.
    template <typename Work>
    decltype(auto) timed(const std::string &name, Work &&work)
    {
      return clock_.timed(name, std::forward<Work>(work));
    }

    /// Every stage run so far, in order, with its wall and CPU time.
    std::vector<StageTiming> timings() const { return clock_.timings(); }

    /// "mesh": the FE model of `bar` on the mesh `parameters` describe; then,
    /// with Refinement = adaptive, "refinement": refined towards the band
    /// that `band` reads off the initial mesh, with progress lines every
    /// `progress_every` seconds (0: none). Returns the refinement's notes.
    /// The mesh refers to `bar`, which must outlive the runner's use of it.
    std::vector<std::string> mesh(const BarModel &bar, const DiscretisationParameters &parameters,
                                  const std::function<double(const Discretisation &)> &band,
                                  double progress_every = 0);

    /// "receptance set-up": gamma(w) of the contact node up to `band`.
    void set_up_receptance(const ReceptanceParameters &parameters, double band);

    /// Reads the checkpoint a continuation goes on from (with the model's
    /// harmonic balance, to check it was written for it).
    using Resume = std::function<ContinuationCheckpoint(HarmonicBalance &)>;

    /// "harmonic balance": the harmonic balance on the receptance, the
    /// internal resonances below the branch, and the backbone, traced from
    /// grazing or, given `resume`, on from the checkpoint it reads.
    void harmonic_balance(const HarmonicBalanceParameters &parameters, const ContactParameters &contact,
                          const BranchParameters &branch, const Resume &resume = {});

    Discretisation                       &discretisation() { return *discretisation_; }
    const Discretisation                 &discretisation() const { return *discretisation_; }
    const Receptance                     &receptance() const { return *receptance_; }
    HarmonicBalance                      &hb() { return *hb_; }
    const HarmonicBalance                &hb() const { return *hb_; }
    const std::vector<InternalResonance> &resonances() const { return resonances_; }
    Backbone                             &backbone() { return backbone_; }
    const Backbone                       &backbone() const { return backbone_; }

  private:
    StageClock                            clock_;
    std::unique_ptr<Discretisation>       discretisation_;
    std::unique_ptr<Receptance>           receptance_;
    std::unique_ptr<HarmonicBalance>      hb_;
    std::vector<InternalResonance>        resonances_;
    Backbone                              backbone_;
  };
} // namespace nsm
