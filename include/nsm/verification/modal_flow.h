// The FE model's motion against the wall, integrated exactly in time: the
// model of the time verification (mass redistributed, no inertia at the
// contact DoF) is linear on each side of the contact switch, so between
// switches the motion is a sum of its modes, and the switches are located
// as roots of the contact DoF's gap (free) or of the wall's force (on the
// wall). No time step: the only errors are round-off and the roots' bisection.
//
// Free, the contact DoF is in static balance, u_N = -K_NI u_I / K_NN, and
// the DoFs with inertia obey M~ u_I'' + (K_II - K_IN K_NI / K_NN) u_I = 0.
// On the wall, u_N = g0 and M~ u_I'' + K_II u_I = -K_IN g0; the wall's force
// K_NI u_I + K_NN g0 must stay <= 0. The switch from one to the other
// happens where both give the same acceleration (gap or force zero), so the
// vector field is continuous there and the flow's tangent is the product of
// each regime's tangents: the saltation matrix is the identity.
#pragma once

#include <nsm/model/contact_law.h>
#include <nsm/model/discretisation.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace nsm
{
  /// State of the DoFs with inertia (all but the clamp and the contact DoF).
  struct ModalState
  {
    dealii::Vector<double> u, v;
  };

  /// Derivatives of a state with respect to some parameters, one per column.
  struct ModalTangents
  {
    dealii::LAPACKFullMatrix<double> du, dv;
  };

  /// What a stretch of motion did at the wall.
  struct WallRecord
  {
    double       time_on_wall = 0;
    double       max_force    = 0; ///< largest force of the wall, >= 0
    unsigned int switches     = 0;
  };

  class ModalFlow
  {
  public:
    ModalFlow(const Discretisation &discretisation, const ContactLaw &law);

    /// The DoFs with inertia, in the order of a ModalState.
    const std::vector<unsigned int> &dofs() const { return dofs_; }

    const ContactLaw &law() const { return law_; }

    /// Advances `state` by `duration`, switching at every contact event;
    /// `tangents` (if any) are carried along.
    WallRecord advance(ModalState &state, double duration, ModalTangents *tangents) const;

    /// The contact DoF's displacement in state u (g0 on the wall).
    double contact_displacement(const dealii::Vector<double> &u) const;

    /// u on every DoF (clamp, contact DoF in balance) from u on the DoFs with inertia.
    dealii::Vector<double> nodal(const dealii::Vector<double> &u) const;

    /// u^T K u / 2 of the nodal displacement of u.
    double strain_energy(const dealii::Vector<double> &u) const;

    /// v^T M~ v / 2.
    double kinetic_energy(const dealii::Vector<double> &v) const;

  private:
    /// One side of the switch: mass-normalised modes, the static offset,
    /// and the switch function e = constant + weights . q (positive: switch).
    struct Regime
    {
      dealii::LAPACKFullMatrix<double> modes;      ///< Phi, columns
      dealii::LAPACKFullMatrix<double> projection; ///< Phi^T M~
      dealii::Vector<double>           omega, offset, weights;
      double                           constant = 0;
    };

    Regime make_regime(bool on_wall) const;

    /// Which regime a state is in: on the wall when free balance would put
    /// the contact DoF beyond it.
    bool on_wall(const ModalState &state) const;

    /// Time to the next switch within `duration` (or duration if none), for
    /// modal amplitudes a (cos) and b (sin).
    double next_switch(const Regime &r, const dealii::Vector<double> &a, const dealii::Vector<double> &b,
                       double duration, bool just_switched) const;

    /// The switch function at time s of a stretch with amplitudes a, b.
    double switch_function(const Regime &r, const dealii::Vector<double> &a, const dealii::Vector<double> &b,
                           double s) const;

    /// Amplitudes a (of cos) and b (of sin) of a state in a regime.
    void amplitudes(const Regime &r, const ModalState &state, dealii::Vector<double> &a,
                    dealii::Vector<double> &b) const;

    /// Moves a state and its tangents by tau within one regime.
    void move(const Regime &r, ModalState &state, ModalTangents *tangents, double tau) const;

    /// Largest wall force over [0, tau] of a stretch on the wall.
    double largest_force(const Regime &r, const dealii::Vector<double> &a, const dealii::Vector<double> &b,
                         double tau) const;

    const ContactLaw                 law_;
    std::vector<unsigned int>        dofs_;
    unsigned int                     contact_, clamp_;
    dealii::LAPACKFullMatrix<double> mass_, stiffness_; ///< on the DoFs with inertia: M~_II, K_II
    dealii::Vector<double>           coupling_;          ///< K_IN
    double                           k_nn_ = 0;
    double                           min_step_ = 0;     ///< shortest step of the switch search
    Regime                           free_, wall_;
  };
} // namespace nsm
