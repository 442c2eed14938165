// A distributed drive's share in the receptance's modes: for the load vector
// f of a drive F f cos(W t) (Forcing/Shape = uniform: f = Discretisation::
// unit_load()) and the mass-normalised clamped-free modes phi_j summed by the
// receptance, the cross weights s_j = phi_j(L) phi_j^T f (the drive's response
// at the contact DoF, sum_j s_j / (w_j^2 - w^2)) and the self weights
// (phi_j^T f)^2 (its energy and the power it puts in). The modes not summed
// respond quasi-statically: e_N^T (K - w^2 M)^{-1} f less the summed modes'
// share is c_0 + c_1 w^2 up to a term (w^2 / w_far^2)^2 of it, with c_0 and
// c_1 from one static solve (as the receptance's truncated basis keeps its
// own remainder, to the same order). The drive acts at the first harmonic
// only, w = W, where a full basis's band puts the far modes at w_far >= 4 M W:
// that term is below (1 / (16 M^2))^2 = 4e-3 / M^4 of the far modes' share.
#pragma once

#include <nsm/model/receptance.h>
#include <nsm/scene/forcing_parameters.h>

#include <deal.II/lac/vector.h>

#include <array>
#include <memory>
#include <vector>

namespace nsm
{
  struct LoadModes
  {
    /// s_j = phi_j(L) phi_j^T f per mode of the receptance's modes().
    std::vector<double> cross;
    /// (phi_j^T f)^2 per mode.
    std::vector<double> self;
    /// {c_0, c_1} of the modes not summed: of e_N^T (K - w^2 M)^{-1} f, and
    /// of f^T (K - w^2 M)^{-1} f.
    std::array<double, 2> cross_far{}, self_far{};
  };

  /// `load` on the discretisation's DoFs (its clamped DoF's entry is left
  /// out); `receptance` must use the modal method.
  LoadModes load_modes(const Receptance &receptance, const dealii::Vector<double> &load);

  /// The modes of Forcing/Shape's drive for the damped receptance: none
  /// (nullptr) at the contact end, whose weights are the receptance's own;
  /// the unit load's along the bar for uniform.
  std::unique_ptr<LoadModes> drive_modes(const Receptance &receptance, const Discretisation &discretisation,
                                         ForcingShape shape);
} // namespace nsm
