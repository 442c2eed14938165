// The forced response: one frequency-response curve per drive amplitude F,
// traced in W by pseudo-arclength on LOCA's stepper through its folds, from
// Continuation/Omega min to Omega max (harmonic_balance/forced_harmonic_balance.h).
#pragma once

#include <nsm/harmonic_balance/forced_harmonic_balance.h>
#include <nsm/scene/continuation_parameters.h>
#include <nsm/scene/harmonic_balance_parameters.h>

#include <optional>
#include <vector>

namespace nsm
{
  /// What a curve is traced in: the drive's frequency W at a fixed F (a
  /// frequency-response curve), or its amplitude F at a fixed W.
  enum class ForcedSweep
  {
    omega,
    forcing
  };

  struct ForcedPoint
  {
    /// 0, 1, ...: a new segment starts after each leap (do not join points
    /// of different segments).
    unsigned int        segment;
    double              omega;
    double              forcing;
    ForcedMeasures      measures;
    double              residual; ///< unscaled 2-norm of R
    bool                stable;   ///< ForcedHarmonicBalance::stable's verdict
    std::vector<double> x;
  };

  struct ForcedCurve
  {
    ForcedSweep              sweep = ForcedSweep::omega;
    /// The drive's amplitude (W sweeps), or the largest (F sweeps).
    double                   forcing;
    /// The drive's fixed frequency (F sweeps).
    double                   omega = 0;
    std::vector<ForcedPoint> points;
    /// LOCA reached an end of the range; false: a step failed at Min step,
    /// Max steps ran out, or the last run was cut (it came back along the
    /// curve, or onto the linear response), and no restart went on.
    bool         finished = false;
    /// Steps LOCA accepted whose residual missed the scene's tolerance: not
    /// written.
    unsigned int rejected = 0;
    /// Times the stepper started again from the curve's last point after
    /// every step failed there (continuation_constants::forced_restarts).
    unsigned int restarts = 0;
    /// Leaps: where no start from the last point goes on, a fixed-W solve
    /// at growing distances ahead (up to Search reach) starts a new segment.
    unsigned int leaps = 0;
    /// Points dropped where the stepper came back along the curve after
    /// turning at a corner onto the branch it came on, or went round a
    /// closed loop of the curve again.
    unsigned int retraced = 0;
    /// Times Min step was made a tenth at a stall nothing else went on
    /// from (continuation_constants::forced_min_step_refinements).
    unsigned int min_step_refinements = 0;
    /// Not traced whole because Continuation/Max steps points were written.
    bool         out_of_steps = false;
    /// Where two traces of a curve meet.
    enum class Meeting
    {
      none,
      joined,  ///< the far trace ran along the first trace's path, and ends where it joins it
      near_end ///< no first trace: the far trace reached the near end
    };
    /// Where the trace from the range's near end stopped before its far
    /// end (or its start converged nowhere): the curve traced again from
    /// the far end towards it, as a segment of its own (trace_forced_curve).
    struct FromFarEnd
    {
      double       stopped;  ///< the swept parameter where the trace from the near end stopped (NaN: its start converged nowhere)
      double       reached;  ///< where the trace from the far end stopped (NaN: it wrote no point)
      unsigned int points;   ///< the points it wrote
      /// Whether and where the traces meet (the curve is whole).
      Meeting meeting;
      bool    met() const { return meeting != Meeting::none; }
    };
    std::optional<FromFarEnd> from_far_end;

    /// Traced over its whole range: to its far end, or from both ends to a
    /// meeting, and with no leap (which jumps over a stretch). A curve with a
    /// stretch no trace reached may have its peak there.
    bool whole() const { return (finished && leaps == 0) || (from_far_end && from_far_end->met() && leaps == 0); }
  };

  /// The curve of amplitude `forcing` over [omega_min, omega_max], from the
  /// linear response's guess (no contact) at omega_min, with the scene's
  /// step bounds and Max steps (points kept over all the stepper's runs;
  /// points a run retraced and dropped free their budget). Where
  /// every step fails, the stepper starts again from the last point in the
  /// direction that leaves the point before it behind, enters the contact
  /// branch where the linear response meets the wall, or leaps ahead in W
  /// onto the last point's motion, as the backbone's continuation does at a
  /// stall. Where nothing goes on before omega_max, the curve is traced
  /// again, as a new segment, from the linear response's guess at omega_max
  /// down (with the same restarts, and leaps onto any motion): a light
  /// damping's curve can stop at a fold the stepper does not turn, and its
  /// side above the resonance is then traced from there; only where that
  /// trace writes nothing does the first leap onto another motion. Where
  /// the start at omega_min converges nowhere, the trace from omega_max is
  /// the curve (segment 0).
  ForcedCurve trace_forced_curve(ForcedHarmonicBalance           &hb,
                                 const HarmonicBalanceParameters &harmonic_balance,
                                 const ContinuationParameters    &continuation,
                                 double                           omega_min,
                                 double                           omega_max,
                                 double                           forcing);

  /// The curve at the drive's frequency `omega` over F up to forcing_max,
  /// traced as a frequency-response curve is, in the load F / forcing_max
  /// with the scene's steps as shares of its Omega range (Omega max - Omega
  /// min), from the linear response at the first step's load to 1.
  ForcedCurve trace_force_curve(ForcedHarmonicBalance           &hb,
                                const HarmonicBalanceParameters &harmonic_balance,
                                const ContinuationParameters    &continuation,
                                double                           omega,
                                double                           forcing_max);
} // namespace nsm
