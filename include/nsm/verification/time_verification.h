// Verification in time: a backbone point's state at t = 0 integrated over
// whole periods on the same FE model, with the physical wall of the contact
// law: rigid (u(L) <= g0) or compliant (a unilateral spring beyond g0).
// The scheme (doc/method.md): mass redistribution, no inertia at the contact
// DoF (Khenous, Laborde, Renard 2008), Newmark's average acceleration for
// the rest, and the one-node contact condition solved
// exactly at each step: the contact DoF, without inertia, is in static
// balance at every t_{n+1}, free of the wall or held by it (on the rigid
// wall's face, or where the compliant wall's spring balances it).
#pragma once

#include <nsm/model/contact_law.h>
#include <nsm/base/band_cholesky.h>
#include <nsm/model/discretisation.h>
#include <nsm/verification/fields.h>
#include <nsm/scene/output_parameters.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <optional>
#include <vector>

namespace nsm
{
  class Progress;

  struct TimeVerification
  {
    double periodicity_defect;     ///< max over DoFs of |u(T) - u(0)| / g0
    double periodicity_defect_end; ///< the same after the last period
    double energy_drift;           ///< (E_end - E_0) / E_0, E with the redistributed mass
    double impulse;                ///< contact impulse per period, mean over the periods
    double contact_fraction;       ///< share of the steps with the wall pushing the contact DoF
    double energy_start;           ///< E_0: the integrator's energy of the state at t = 0 (as energy())
  };

  /// The FE mass matrix without inertia at the contact DoF: its row and
  /// column are removed and the mass they carried goes to the diagonal of
  /// the DoFs they coupled, in proportion to the coupling.
  dealii::SparseMatrix<double> redistributed_mass(const Discretisation &discretisation);

  class ContactTimeIntegrator
  {
  public:
    ContactTimeIntegrator(const Discretisation &discretisation,
                          const ContactLaw     &law,
                          double                period,
                          unsigned int          steps_per_period);

    /// Removes a penetration u_N > g0 of the rigid wall with the static shape
    /// K^{-1} e_N (moving the contact DoF alone would add spurious strain
    /// energy). A compliant wall admits every u.
    void make_admissible(dealii::Vector<double> &u) const;

    /// Integrates from (u0, v0) over `periods` periods; u0 must be admissible.
    TimeVerification run(const dealii::Vector<double> &u0,
                         const dealii::Vector<double> &v0,
                         unsigned int                  periods) const;

    /// The clamp as a unit row and column.
    static void constrain_clamp(dealii::SparseMatrix<double> &matrix, unsigned int clamp);

    /// (v^T M~ v + u^T K u) / 2 plus the energy the wall stores.
    double energy(const dealii::Vector<double> &u, const dealii::Vector<double> &v) const;

  private:
    /// One step: u, v, a at t_n become those at t_{n+1}; returns the contact
    /// force at t_{n+1} (<= 0: the wall pushes in -x).
    double step(dealii::Vector<double> &u, dealii::Vector<double> &v, dealii::Vector<double> &a) const;

    /// M~ a_0 = -K u_0 on the DoFs with inertia.
    dealii::Vector<double> initial_acceleration(const dealii::Vector<double> &u) const;

    /// M~ with a unit diagonal at the contact DoF and the clamp.
    dealii::SparseMatrix<double> inertia_matrix() const;

    /// 4/dt^2 M~ + K, the matrix of each step.
    dealii::SparseMatrix<double> step_matrix() const;

    const ContactLaw                law_;
    const double                    dt_;
    const unsigned int              steps_;
    const unsigned int              contact_, clamp_;
    dealii::SparseMatrix<double>    mass_;      ///< redistributed: no row or column at the contact DoF
    dealii::SparseMatrix<double>    stiffness_; ///< with the clamp as a unit row and column
    BandCholesky                    step_solver_, static_solver_, mass_solver_;
    dealii::Vector<double>          contact_response_; ///< step matrix^{-1} e_N
  };

  /// A point's verification against its own harmonic balance.
  struct PointVerification
  {
    TimeVerification time;
    double           impulse_ratio; ///< time integration's impulse over the HB's, T lambda_0
    bool             verified;      ///< periodicity_defect <= Output/Verify tolerance
  };

  /// Verifies a field's point: its state at t = 0 made admissible, integrated
  /// against the wall of `law` with the Output/Verify settings.
  PointVerification verify_in_time(const PeriodicField &field, const Discretisation &discretisation,
                                   const ContactLaw &law, const OutputParameters &output);

  /// Verifies every Verify every-th backbone point and every Fields every-th
  /// (the fields' points), against hb's contact law; empty for the others.
  /// A point `known` holds (a resumed run's, verification_checkpoint.h) is
  /// taken from it, not integrated again.
  std::vector<std::optional<PointVerification>> verify_backbone(
    HarmonicBalance                                     &hb,
    const Discretisation                                &discretisation,
    const Backbone                                      &backbone,
    const OutputParameters                                 &output,
    Progress                                            &progress,
    const std::vector<std::optional<PointVerification>> &known = {});
} // namespace nsm
