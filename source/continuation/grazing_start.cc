#include <nsm/base/errors.h>
#include <nsm/base/text.h>
#include <nsm/continuation/constants.h>
#include <nsm/continuation/grazing_start.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace nsm
{
  namespace
  {
    std::string text(const double value) { return significant(value, 6); }

    /// The branch leaves grazing beyond the range's far end: the range holds
    /// none of it, whatever Newton does.
    [[noreturn]] void range_misses_branch(const BranchContext &context, const unsigned int mode, const double w,
                                          const double start)
    {
      const bool        up = context.direction > 0;
      std::ostringstream s;
      s.precision(6);
      s << "parameter 'Continuation/" << (up ? "Omega max" : "Omega min") << "' = " << context.far_end
        << " is out of range: allowed " << (up ? "above" : "below") << " Omega = " << start
        << ", where the branch of clamped-free mode " << mode << " (w = " << w << ") leaves grazing "
        << (up ? "upwards (Contact/Force sign = physical)" : "downwards (Contact/Force sign = seed-eq5)");
      throw RangeOutsideBranch(s.str());
    }

    /// Steps are absolute: one of Min step must move Omega near w by more
    /// than its rounding, or every step near the branch is lost in it (a bar
    /// of length 1e-20 has w_1 = 1.6e20, where Omega's spacing is 3e4).
    void check_steps_resolve(const ContinuationParameters &c, const double w)
    {
      const double resolution = continuation_constants::step_ulps * std::numeric_limits<double>::epsilon() * w;
      if (c.min_step >= resolution)
        return;
      std::ostringstream s;
      s.precision(3);
      s << "parameter 'Continuation/Min step' = " << c.min_step << " is out of range: allowed at least " << resolution
        << " here, where the branch starts at w = " << w << " (" << static_cast<int>(continuation_constants::step_ulps)
        << " times Omega's rounding there): the steps are absolute, so scale Initial step, Min step and Max step "
           "with the frequencies that Bar/Length, Young modulus and Density set";
      throw InputError(s.str());
    }

    /// What the contact law's gap weight a makes of a gamma(0).
    std::string weight_note(const ContactParameters &contact, const double gamma0)
    {
      std::ostringstream s;
      if (contact.wall == Wall::rigid)
        s << "Contact/Alpha = " << contact.alpha << " gives alpha gamma(0) = " << contact.alpha * gamma0
          << " (the contact law's switch lambda - alpha g balances force and gap for alpha gamma(0) near 1, "
             "where the start converges most easily)";
      else
        s << ContactLaw(contact).stiffness_note(gamma0);
      return s.str();
    }

    /// The grazing start's Newton solves: how many, and how many ended at
    /// Harmonic balance/Max iterations.
    struct StartTally
    {
      unsigned int solves = 0, at_limit = 0;
    };

    [[noreturn]] void no_start(const BranchContext &context, const unsigned int mode, const double w,
                               const StartTally &tally)
    {
      std::ostringstream s;
      s << "no converged non-trivial solution within Continuation/Search reach = "
        << text(context.params.continuation.search_reach) << " (relative) of grazing of clamped-free mode " << mode
        << " (w = " << w << ") and before the end of Continuation/Omega min..max";
      if (tally.at_limit > 0)
        s << "; " << tally.at_limit << " of " << tally.solves
          << " Newton solves stopped at Harmonic balance/Max iterations = "
          << context.params.harmonic_balance.iterations() << " (more may converge)";
      s << "; " << weight_note(context.params.contact, context.hb.receptance()(0.0).gamma);
      throw NumericalError(s.str());
    }
  } // namespace

  BackbonePoint start_at_grazing(BranchContext &context, Backbone &backbone)
  {
    const auto                &c     = context.params.continuation;
    const unsigned int         mode  = c.mode;
    const std::vector<double> &poles = context.hb.receptance().poles();
    if (mode > poles.size())
      {
        const std::string band = "Harmonics x Omega max = " +
                                 text(context.params.harmonic_balance.harmonics * c.omega_max);
        throw InputError("parameter 'Continuation/Mode' = " + std::to_string(mode) + " is out of range: " +
                         (poles.empty() ? "no clamped-free mode lies below " + band + "; allowed: a larger Omega max" :
                                          "allowed 1 to " + std::to_string(poles.size()) +
                                            " (clamped-free modes below " + band + ")"));
      }
    const double w = std::sqrt(poles[mode - 1]);
    check_steps_resolve(c, w);
    // The contact lasts a vanishing share of the period at grazing; Search
    // reach (5 %) of w_j away the branch is far beyond its grazing end. A
    // start before the range is traced up to it; one beyond it has no point
    // in it.
    if (const double start = w * (1 + context.direction * c.grazing_offset); context.beyond(start, context.far_end))
      range_misses_branch(context, mode, w, start);
    StartTally tally;
    for (double offset = c.grazing_offset; offset < c.search_reach; offset *= continuation_constants::search_growth)
      {
        const double omega = w * (1 + context.direction * offset);
        if (context.beyond(omega, context.far_end))
          break;
        context.hb.set_omega(omega);
        const std::vector<double> guess = context.hb.grazing_guess();
        BackbonePoint             point;
        if (guess.empty())
          continue;
        ++tally.solves;
        if (!context.solve(omega, guess, 0, point))
          {
            tally.at_limit += context.last_failure() == BranchContext::SolveFailure::iteration_limit;
            continue;
          }
        std::ostringstream s;
        s.precision(10);
        s << "start at grazing of clamped-free mode " << mode << " (w = " << w << ") at Omega = " << omega;
        backbone.events.push_back(s.str());
        if (point.measures.energy > c.energy_max)
          throw InputError("parameter 'Continuation/Energy max' = " + text(c.energy_max) +
                           " is out of range: allowed above the energy at grazing, " +
                           text(point.measures.energy));
        const bool before = context.beyond(context.near_end, omega);
        context.span      = std::abs(context.far_end - (before ? context.near_end : omega));
        return point;
      }
    no_start(context, mode, w, tally);
  }
} // namespace nsm
