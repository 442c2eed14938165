// The continuation's algorithm constants, each named once with its reason.
// What a user may need to tune is a scene parameter (Continuation/...).
#pragma once

namespace nsm::continuation_constants
{
  /// A step Newton solved in at most this many iterations was easy: the next
  /// one may be longer.
  constexpr unsigned int easy_iterations = 4;
  /// How much longer, up to BranchContext::max_step().
  constexpr double step_growth = 1.5;
  /// A failed step or a jump to another branch divides the step by this: at
  /// a fold every smaller step fails too, so the step shrinks fast.
  constexpr double step_shrink = 4;
  /// Steps never exceed the range covered so far divided by this, so that a
  /// narrow range still gets points.
  constexpr double steps_per_span = 10;
  /// A leap starts far from the solution: its retry with a line search gets
  /// this many times Max iterations.
  constexpr unsigned int leap_iteration_factor = 2;
  /// A leap's distances from the fold, and the grazing start's offsets, grow
  /// by this factor up to Search reach: a doubling search covers the reach
  /// in a few solves.
  constexpr double search_growth = 2;
  /// The fewest units of Omega's rounding a step of Min step must span near
  /// the branch's start: below it the steps' arithmetic is rounding alone.
  constexpr double step_ulps = 1024;
  /// LOCA's adaptive step size control: its default aggressiveness.
  constexpr double loca_aggressiveness = 1.0;
  /// LOCA tests the norm of its extended (arclength) system: its corrector
  /// converges to this fraction of the Newton tolerance, so that the HB
  /// residual of a step it accepts meets the scene's tolerance.
  constexpr double loca_corrector_tolerance_factor = 0.1;
  /// A forced curve's stepper starts again from its last point at most this
  /// many times (forced_response.h): on the seed bar's curves each corner
  /// needs one.
  constexpr unsigned int forced_restarts = 50;
  /// Where nothing else goes on from a forced curve's stall, Min step is
  /// made a tenth and the restarts are tried again, at most this many
  /// times: a fold sharper than Min step resolves (the seed bar's curve in F
  /// at W = 1.97 turns 1.2e-7 of its load past grazing, where the scene's
  /// Min step over a range of 0.5 is 2e-6) is turned with a finer one.
  constexpr unsigned int forced_min_step_refinements = 2;
  /// Each such refinement divides Min step by this.
  constexpr double forced_min_step_division = 10;
  /// A forced curve's stepper has come back along the curve (or gone round
  /// a loop of it again) where this many points in a row run along the path
  /// traced before them against its direction (or in it), each
  /// within retrace_share of a chord's length from a chord between two
  /// earlier consecutive points of its verdict (the stepper's metric).
  /// Measured against the direction on prm/forced.prm and its uniform drive:
  /// points that retrace lie 0.001 to 0.27 of a chord off it, mostly below
  /// 0.1; a curve's own folds and ripples come within 0.065 to 0.3 of its
  /// other side at one to three points in a row. In the direction, on a
  /// scan of 72 curves (doc/log.md, stop 77): the cut acts on the one curve
  /// that goes round a loop and leaves every other curve's points as they
  /// were.
  constexpr unsigned int retrace_points = 5;
  constexpr double       retrace_share  = 0.1;
  /// A trace from the far end joins the first trace where retrace_points of
  /// its points lie within retrace_share of the first trace's path, and
  /// between them points within this, the most that retracing points
  /// measured lie off it (above): the join begins at the first of them.
  constexpr double retrace_share_most = 0.3;
  /// The first move of the contact force's mean (over F_s = g0 / gamma(0),
  /// the force that closes the gap statically) by which a forced curve
  /// leaves a corner whose branch turns back (then tenths of it, to 1e-4
  /// of it): a thousandth of the force that closes the gap keeps the
  /// landing within the step's guard of a grazing point.
  constexpr double contact_share = 1e-3;
  /// The largest impulse (its period mean over F_s) of the contact force by
  /// which a forced curve that has come down its linear response to the wall
  /// enters the contact branch there (then tenths of it, to 1e-4 of it):
  /// the landings measured on four curves (prm/forced.prm, M = 40 and 80)
  /// came from 1e-4 and 1e-5, 2e-6 to 1.6e-5 of W from the grazing point.
  constexpr double grazing_impulse = 0.1;
  /// The spectral criterion looks at harmonics from this one up: k = 0 is
  /// the static part, 1 the fundamental, and 2 has no oscillating neighbour
  /// of its parity below it.
  constexpr unsigned int first_compared_harmonic = 3;
} // namespace nsm::continuation_constants

namespace nsm::continuation_constants
{
  /// A tongue is named w_j / k only if its points' Omega interval lies within
  /// this share of w_j / k: the feet of the tongues measured on the uniform,
  /// seed, stepped and 1 + x^2 bars and the seed's mode 2 lie within 0.82 %
  /// of their resonance, the misnamed ones 1.6 % to 6.7 % away.
  constexpr double resonance_name_tolerance = 0.01;
  /// The gap search's secant predictor spans this share of Omega behind the
  /// gap's start: longer than the steps (up to 0.01) so that one step's
  /// noise does not steer it, short enough to follow the branch's bend.
  constexpr double trend_base = 0.01;
  /// The gap search starts Newton at this many Omegas per Fill gaps wider
  /// than: a landing lies at most an eighth of that width from a start.
  constexpr unsigned int gap_starts_per_width = 8;
  /// The branch's climb into the accumulation point W_acc of its internal
  /// resonances, and the motions of near half contact beside its top, reach
  /// beyond it by a truncation effect that falls like M^-2: the climb's top
  /// lies 8.7e-4, 2.2e-4, 5.5e-5, 1.7e-5 beyond pi / 2 at M = 20, 40, 80, 160
  /// on 1 + 0.2 x (FE_Q(10) x 20), about 0.35 / M^2 (0.22 and 0.24 / M^2 at
  /// M = 20 and 40 on FE_Q(1) x 4000); at M = 40, the points of
  /// contact fraction above 0.35 beyond pi / 2 reach 0.34 / M^2 (relative)
  /// on 1 + 0.2 x, 1 + 0.3 x^3 and 1 + 0.05 x, 1.9 / M^2 on 1 + x and 1 + x^2.
  /// The labels take the accumulation point as passed at
  /// W_acc (1 + this / M^2) along the branch, twice the farthest. The
  /// climb's truncated zone is looked for as deep below W_acc
  /// (accumulation_tongue.h): the estimate's zone, 4 times M's, reached 0.2
  /// to 2.1 / M^2 below it on those bars at M = 40 (doc/log.md); a branch
  /// that starts within it does not climb.
  constexpr double accumulation_reach = 4;
  /// The climb's truncated zone below W_acc narrows like M^-2 (above), so the
  /// zone of M / 2 harmonics, where the error estimate |E(M/2) / E(M) - 1|
  /// exceeds Tongue share, reaches (M / (M / 2))^2 = 4 times as far below
  /// W_acc as the zone of M. Measured against M = 160 on 1 + 0.2 x (FE_Q(1)
  /// x 4000): at M = 40 the estimate exceeds 0.02 from 4.2e-4 below W_acc,
  /// and the run's energy leaves M = 160's by more than 0.02 between 1.7e-4
  /// and 1.2e-4 below it; at M = 20, 1.5e-3 and between 5.3e-4 and 4.1e-4.
  constexpr double halved_truncation_reach = 4;
} // namespace nsm::continuation_constants
