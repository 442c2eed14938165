// The forced harmonic balance's model at the contact DoF in the receptance's
// modal coordinates q_j = phi_j(L) eta_j, stepped in time with the physical
// wall (forced_time_verification.h has the equations): Newmark's average
// acceleration per mode makes u(L, t_{n+1}) linear in the wall's force
// P(t_{n+1}), which then follows in closed form (ContactLaw::step_force).
// Each step can also carry tangents, the step's derivative applied to
// perturbations of the modes' (q, v, a): exact for the discrete map, whose
// wall force is piecewise linear in the state (forced_floquet.h).
#pragma once

#include <nsm/harmonic_balance/forced_harmonic_balance.h>

#include <vector>

namespace nsm
{
  class ForcedModalSteps
  {
  public:
    /// At t = 0 on the point x of `hb` (its current Omega and forcing),
    /// `steps` steps a period.
    ForcedModalSteps(const ForcedHarmonicBalance &hb, const std::vector<double> &x, unsigned int steps);

    /// Perturbations of every mode's q, v and a (each of size modes()).
    struct Tangent
    {
      std::vector<double> q, v, a;
    };

    /// One step, the tangents (if any) carried along; returns u(L, t).
    double step(std::vector<Tangent> *tangents = nullptr);

    /// The instantaneous energy at the last step (the harmonic balance's
    /// definition: the modes', the far modes' static share, the wall's).
    double energy() const;

    unsigned int modes() const { return modes_.size(); }
    double       tip() const { return u_; }

    /// Every mode's q, then every mode's v.
    std::vector<double> state() const;
    /// Back to t = 0 with the modes' q and v (as state() gives them), the
    /// accelerations and the wall's force those of the equation of motion.
    void restart(const std::vector<double> &state);

    /// The tangent of a perturbation of mode j's q (or v) at t = 0, with
    /// the accelerations that keep the equation of motion: a_k = r_k dP -
    /// c_k v_k - w_k^2 q_k, dP the wall force's change.
    Tangent start_tangent(unsigned int j, bool velocity) const;

  private:
    struct Mode
    {
      double residue, drive, eigenvalue, damping;
      double q, v, a;
    };

    const ContactLaw   &law_;
    double              omega_, forcing_, far_, dt_;
    DampedReceptance::DriveFactors drive_far_;
    std::vector<Mode>   modes_;
    unsigned long long  step_ = 0;
    double              force_ = 0, u_ = 0, drive_ = 0;
    /// Per mode, Newmark's scale and q_{n+1}'s response B_j to the wall's
    /// force (fixed by dt); u(L)'s response far + sum_j B_j.
    std::vector<double> scale_, slope_;
    double              response_ = 0;
    /// Per mode, the step's A_j (q_{n+1} = A_j + B_j P_{n+1}).
    std::vector<double> constant_;
  };
} // namespace nsm
