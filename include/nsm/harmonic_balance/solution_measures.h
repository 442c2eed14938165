// What a user reads of one periodic solution of the harmonic balance: its
// energy over the period (mean, spread, share per harmonic) from the
// receptance fields in closed form, and the contact force and gap over the
// period. The harmonic balance supplies the solution in its angle variables.
#pragma once

#include <nsm/harmonic_balance/active_set.h>
#include <nsm/harmonic_balance/series_samples.h>
#include <nsm/model/contact_law.h>
#include <nsm/harmonic_balance/trigonometric.h>

#include <vector>

namespace nsm
{
  /// Quantities of one converged (or candidate) periodic solution.
  struct PeriodicSolutionMeasures
  {
    double energy;            ///< period mean of kinetic + strain energy (+ a compliant wall's)
    double energy_spread;     ///< (max - min) / mean over the period
    double max_contact_force; ///< max over the period of lambda(t)
    double max_contact_displacement = 0; ///< max over the period of |u(L, t)|: the contact end's amplitude
    double contact_fraction;  ///< share of the period in contact (q > 0, ContactLaw)
    double min_force;         ///< min lambda / max lambda (both walls: >= 0)
    double min_gap;           ///< min g / g0 (rigid wall: >= 0; compliant: its deepest penetration)
    double max_complementarity; ///< max |lambda g| / (max lambda g0) (rigid wall: 0)
    /// The harmonic k >= 1 of the largest amplitude of u(L, t): 1 on the
    /// mode's main branch, whose contact end swings once a period.
    unsigned int leading_harmonic = 1;
  };

  /// The harmonic k >= 1 whose cosine and sine coefficients of `functions`
  /// have the largest sum of squares (the lowest of equal ones); 1 if the
  /// basis holds none.
  unsigned int leading_harmonic(const TrigonometricBasis &functions, const std::vector<double> &coefficients);

  /// gamma(k W) = tan(theta) at the frequency of harmonic k.
  struct HarmonicPhase
  {
    double cos, sin, dtheta_domega; ///< of theta at frequency k W
    double omega2;                  ///< (k W)^2
    double dtheta_domega2;          ///< d theta / d(w^2) = gamma' cos^2
  };

  /// A solution at one W: basis function i carries c_i = scale x_i, its
  /// contact force a_i = c_i cos(theta) and displacement b_i = -s c_i
  /// sin(theta), theta that of harmonic order[i]. The references must
  /// outlive the measures' calls.
  struct PhasedSolution
  {
    const TrigonometricBasis         &functions;
    const std::vector<HarmonicPhase> &phases; ///< per harmonic k = 0..M
    const std::vector<double>        &x;      ///< 0 in the unfolding slot
    double                            scale;
    double                            omega;
  };

  class SolutionMeasures
  {
  public:
    /// The energy is a trigonometric polynomial of degree 2M; its spread is
    /// taken from 4 (2M + 1) points of it.
    explicit SolutionMeasures(unsigned int harmonics);

    /// Period mean and spread of the energy: the bar's, plus what a
    /// compliant wall stores, k max(u - g0, 0)^2 / 2 (its mean exactly, its
    /// spread at the spread's points).
    void energy(const PhasedSolution &solution, const ContactLaw &law, PeriodicSolutionMeasures &result) const;

    /// Period-mean energy of the bar carried by each harmonic k = 0..M
    /// (Parseval: they add up to the bar's mean energy, energy() less a
    /// compliant wall's).
    std::vector<double> harmonic_energies(const PhasedSolution &solution) const;

    /// Largest and least contact force, least gap and largest |lambda g| at
    /// the active set's samples, against the wall of the contact law.
    void force_and_gap(const PhasedSolution &solution, const ActiveSet &samples, const ContactLaw &law,
                       PeriodicSolutionMeasures &result) const;

  private:
    /// The compliant wall's mean energy, lambda (u - g0) / 2 by Parseval.
    double mean_wall_energy(const PhasedSolution &solution, const ContactLaw &law) const;

    /// e += the compliant wall's energy at the spread's points.
    void add_wall_energy(const PhasedSolution &solution, const ContactLaw &law, std::vector<double> &e) const;

    unsigned int harmonics_;
    /// The basis of the energy over the period (1, sin and cos of m tau, m =
    /// 1..2M) and its values at the 4 (2M + 1) points of the spread, by FFT.
    TrigonometricBasis energy_basis_;
    SeriesSamples      energy_samples_;
  };
} // namespace nsm
