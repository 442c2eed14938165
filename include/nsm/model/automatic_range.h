// The Omega range and the energy ceiling a scene leaves to the FE model
// (Continuation/Omega max = 0, Energy max = 0): read off mode j's spectrum
// and its grazing energy, so that a scene that names only its bar gets the
// first nonsmooth mode from grazing to near its high-energy limit.
#pragma once

#include <nsm/model/discretisation.h>
#include <nsm/scene/contact_parameters.h>
#include <nsm/scene/continuation_parameters.h>

#include <string>
#include <vector>

namespace nsm
{
  /// Mode j's frequencies and its grazing energy on the FE model.
  struct ModeFrequencies
  {
    double free;     ///< clamped-free w_j: grazing
    /// w_j of the bar held at the wall: clamped-clamped against the rigid
    /// wall; on the compliant wall's spring (k added to the contact DoF's
    /// stiffness) with the physical sign. With eq. (5)'s sign the spring
    /// would pull: the rigid wall's is kept.
    double held;
    bool   on_spring; ///< `held` is the spring's
    /// 2 w_free w_held / (w_free + w_held): half a period free, half
    /// held, the bilinear estimate of the zero-gap (infinite energy) limit;
    /// exact for the uniform bar against the rigid wall (2 pi / 3 against
    /// pi / 2 and pi).
    double bilinear;
    /// E_g = w_j^2 g0^2 / (2 phi_j(L)^2): the energy of the linear mode with
    /// u(L) = g0 (grazing.csv).
    double grazing_energy;
  };

  ModeFrequencies mode_frequencies(const Discretisation &discretisation, unsigned int mode,
                                   const ContactParameters &contact);

  /// Share of the way from w_j to the bilinear estimate at which an
  /// automatic range ends. On the uniform bar the energy there is 40 E_g
  /// (exact: E / E_g = 1 / (T - 3)^2); measured 6 to 50 E_g on six bars
  /// (doc/method.md): far below an automatic Energy max, and short of the
  /// limit, where the branch's energy grows without bound.
  constexpr double automatic_range_share = 0.8;

  /// Where Continuation/Omega max or Energy max is 0, sets it from `d` and
  /// the wall: Omega max = w_j + automatic_range_share (w_bilinear - w_j),
  /// Energy max = Energy max over grazing x E_g. Returns a summary note for
  /// each value set. Throws InputError naming the parameter when Omega min or
  /// a field frequency (Output/Fields at) lies beyond the automatic Omega max.
  std::vector<std::string> resolve_automatic_range(ContinuationParameters &c, const ContactParameters &contact,
                                                   const std::vector<double> &fields_at, const Discretisation &d);
} // namespace nsm
