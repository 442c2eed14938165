// Families of periodic solutions from grazing: sequential continuation in
// Omega (the paper's) and pseudo-arclength (LOCA), with the internal
// resonances W = w_j / k that fold the branch. compute_backbone joins the
// stages of branch_context.h (grazing_start, sequential_steps,
// arclength_steps, leap) into segments, fills the main branch's gaps if the
// scene asks (gap_filling.h), then labels the points (main_branch.h).
#pragma once

#include <nsm/continuation/backbone.h>
#include <nsm/harmonic_balance/harmonic_balance.h>
#include <nsm/continuation/branch_parameters.h>

#include <optional>
#include <string>
#include <vector>

namespace nsm
{
  /// Every W = w_j / k in [Omega min, Omega max] with k <= M, w_j from the
  /// FE clamped-free spectrum up to Harmonics x Omega max; sorted by W.
  std::vector<InternalResonance> internal_resonances(const Receptance       &receptance,
                                                     const BranchParameters &params);

  struct ContinuationCheckpoint;

  /// Starts at grazing of Continuation/Mode, or where `resume` stood (an
  /// interrupted run's checkpoint, checkpoint.h), and follows the branch
  /// with the scene's method. Only converged, non-trivial points are kept.
  /// A resumed continuation computes the points an uninterrupted one does.
  Backbone compute_backbone(HarmonicBalance                      &hb,
                            const BranchParameters               &params,
                            const std::vector<InternalResonance> &resonances,
                            const ContinuationCheckpoint         *resume = nullptr);

  /// Where a point at `omega` solved from points[index] goes among `points`
  /// (segments in the direction of continuation, `direction`): after it if
  /// omega lies beyond it, else before it.
  std::size_t position_beside(const std::vector<BackbonePoint> &points, std::size_t index, double omega,
                              double direction);

  /// The solution at exactly `omega` on the computed branch: Newton from the
  /// interpolation of two backbone points of one segment that bracket it
  /// (each such pair in turn, pairs of main points first; only those if
  /// `main_only`). Otherwise
  /// (omega in the gap a leap left), unless `main_only`, Newton with a line
  /// search, as a leap, from the nearest points below and above and from the
  /// impulsive guess. The point is labelled main, tongue or other against
  /// the labelled backbone (label_point). Throws NumericalError if nothing
  /// converges.
  BackbonePoint solve_on_branch(HarmonicBalance        &hb,
                                const BranchParameters &params,
                                const Backbone         &backbone,
                                double                  omega,
                                bool                    main_only = false);

} // namespace nsm
