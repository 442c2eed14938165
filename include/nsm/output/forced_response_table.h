// frc.csv, the forced response's table, and its Result lines: each curve's
// extent and peak, and the peak against the backbone's main branch.
#pragma once

#include <nsm/base/csv.h>
#include <nsm/continuation/continuation.h>
#include <nsm/continuation/forced_response.h>
#include <nsm/verification/forced_time_verification.h>

#include <optional>

#include <string>
#include <vector>

namespace nsm
{
  /// Why a curve's peak is not compared with the backbone's main branch
  /// (none: it is).
  enum class PeakLeftOut
  {
    none,
    /// A stretch neither trace reached may hold the peak (ForcedCurve::whole).
    not_whole,
    /// The most energy lies at an end of the curve's extent: the curve is
    /// still climbing there, and has no peak inside its range.
    at_range_end,
    /// The peak never touches the wall: the linear response, which the
    /// backbone does not describe.
    linear,
    no_backbone,
    /// No main point of the backbone on one side of the peak's Omega.
    no_main_bracket
  };

  /// A curve's peak (its point of most energy) against the backbone's main
  /// branch, read between the main points that bracket its Omega. The one
  /// place that decides whether a peak is compared: the Result line and the
  /// study both read it.
  struct ForcedPeak
  {
    double omega, energy, phase, contact_fraction;
    /// E / E_main - 1, and the spacing of the main points it is read
    /// between; set exactly when left_out is none.
    std::optional<double> distance, bracket;
    PeakLeftOut           left_out;

    /// A peak inside the range of a curve traced whole, touching the wall:
    /// the motion whose phase lag the backbone check reads.
    bool nonlinear_peak() const
    {
      return left_out == PeakLeftOut::none || left_out == PeakLeftOut::no_backbone ||
             left_out == PeakLeftOut::no_main_bracket;
    }
  };

  /// The peak of a curve with points; `backbone` may be null.
  ForcedPeak forced_peak(const ForcedCurve &curve, const Backbone *backbone);

  /// Per curve, per point: its verification in time, if it has one.
  using ForcedVerifications = std::vector<std::vector<std::optional<ForcedVerification>>>;

  /// One row per point of each curve, in the curves' order and along each;
  /// with `verifications` not empty, the verification columns (empty cells
  /// for a point not verified).
  CsvTable forced_response_table(const std::vector<ForcedCurve> &curves, const ForcedVerifications &verifications,
                                 const std::string &name = "frc.csv");

  /// "forced response F = ..." or "force response at Omega ...": how the
  /// Result lines and events name a curve.
  std::string curve_name(const ForcedCurve &curve);

  /// Why a curve has no point, for its Result line and the run's failure.
  std::string no_point(const ForcedCurve &curve);

  /// The verification's Result line: points and periods; of the points
  /// stable by the fold test, the medians and largest of |A_t / A - 1| (tip
  /// amplitude), |E_t / E - 1| (energy) and the last period's drift, and how
  /// many the integration keeps (A_t within
  /// forced_verification_constants::stays_within of A); of the unstable
  /// ones, how many it leaves.
  std::string forced_verification_summary(const std::vector<ForcedCurve> &curves,
                                          const ForcedVerifications      &verifications);

  /// Per curve: its points and Omega extent, whether it reached the range's
  /// end, its unstable points (the fold test), and its peak (largest energy): Omega, energy, phase lag; with a
  /// backbone (not null), the main branch's energy at the peak's Omega, read
  /// between the main points that bracket it, and the relative distance.
  /// The continuation log's events of the forced response: each change of
  /// the fold test's verdict along a curve, between which points.
  std::vector<std::string> forced_response_events(const std::vector<ForcedCurve> &curves);

  /// Per force-response curve (an F sweep at fixed W): its points and F
  /// extent, how its tracing went, its unstable points (the fold test) and
  /// its point of most energy.
  std::vector<std::string> force_response_summary(const std::vector<ForcedCurve> &curves);

  std::vector<std::string> forced_response_summary(const std::vector<ForcedCurve> &curves,
                                                   const Backbone                 *backbone);
} // namespace nsm
