// The periodic orbit of the FE model, found in time by shooting: the motion
// a harmonic balance point stands for, with none of HB's truncation.
//
// The orbit is even in time, so its velocity vanishes at t = 0 and t = T/2.
// The unknowns are the displacements at t = 0 of the DoFs with inertia (the
// contact DoF follows in static balance, the velocity is zero); the residual
// is their velocity at T/2, after T/2 of the exact flow of modal_flow.h.
// Fixing v(0) = 0 removes the time shift, so the
// Jacobian is square and, for an isolated orbit, regular. Newton's steps are
// least-norm (pseudo-inverse of the Jacobian's SVD): where the orbit is not
// isolated (the uniform bar, doc/method.md) they select the member nearest
// the start. The Floquet multipliers are the eigenvalues of the monodromy
// matrix, the tangent of one whole period on (u, v) of the DoFs with inertia.
#pragma once

#include <nsm/model/contact_law.h>
#include <nsm/model/discretisation.h>

#include <deal.II/lac/vector.h>

#include <complex>
#include <vector>

namespace nsm
{
  struct OrbitSettings
  {
    double       tolerance;         ///< largest |v(T/2)| / (Omega g0) of a converged orbit
    double       stability_margin;  ///< stable: every |multiplier| <= 1 + margin
    bool         floquet = true;    ///< compute the monodromy matrix and its multipliers
  };

  struct PeriodicOrbit
  {
    bool                              converged = false;
    unsigned int                      newton_steps = 0;
    double                            residual = 0;  ///< max |v(T/2)| / (Omega g0)
    dealii::Vector<double>            displacement;  ///< u at t = 0 (v = 0 there)
    double                            energy = 0;    ///< u^T K u / 2 at t = 0
    double                            contact_fraction = 0;  ///< share of the period on the wall
    unsigned int                      switches = 0;  ///< contact switches over one period
    double                            periodicity = 0; ///< max |u(T) - u(0)| / g0 after one period
    double                            max_contact_force = 0; ///< largest force of the wall, >= 0
    double                            isolation = 0; ///< smallest singular value of the shooting Jacobian / Omega
    std::vector<std::complex<double>> multipliers;   ///< Floquet multipliers, nearest 1 first
    double                            floquet_max = 0; ///< largest |multiplier|
    bool                              stable = false;
  };

  /// Shoots from `guess` (nodal displacement at t = 0) to the orbit of
  /// frequency omega on `discretisation` against the wall of `law`.
  /// A guess from which Newton does not converge, or converges to a motion
  /// that never reaches the wall (the bar at rest), gives converged = false.
  PeriodicOrbit find_periodic_orbit(const Discretisation        &discretisation,
                                    const ContactLaw            &law,
                                    double                       omega,
                                    const dealii::Vector<double> &guess,
                                    const OrbitSettings         &settings);
} // namespace nsm
