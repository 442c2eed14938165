#include <nsm/base/errors.h>
#include <nsm/base/interruption.h>
#include <nsm/base/progress.h>
#include <nsm/base/text.h>
#include <nsm/model/automatic_range.h>
#include <nsm/model/band_cells.h>
#include <nsm/model/banded_pencil.h>
#include <nsm/model/spectrum.h>
#include <nsm/scene/scene.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// How far above the band a coarse mesh's counterparts are sought.
    constexpr double band_reach = 2;
    /// The Cells parameter's upper bound (its Patterns).
    constexpr unsigned int most_cells = 1000000;
  } // namespace

  BandAgreement band_agreement(const Discretisation &coarse, const Discretisation &fine, const double top)
  {
    BandAgreement b;
    b.top = top;
    const std::vector<double> theirs = eigenvalues_below(BandedPencil(fine, EndCondition::clamped_free), top);
    const std::vector<double> ours =
      eigenvalues_below(BandedPencil(coarse, EndCondition::clamped_free), band_reach * top);
    b.modes = theirs.size();
    for (std::size_t j = 0; j < theirs.size(); ++j)
      b.error = std::max(b.error, j < ours.size() ? std::abs(std::sqrt(ours[j] / theirs[j]) - 1) :
                                                    band_reach * top / std::sqrt(theirs[j]) - 1);
    return b;
  }

  double continuum_modes_below(const BarModel &bar, const double top)
  {
    return top * bar.travel_time() / M_PI + 0.5;
  }

  namespace
  {
    /// The meshes Cells = 0 tries: cells doubling from max(1, Graded/Layers)
    /// up to half the Cells bound.
    std::vector<unsigned int> candidate_cells(const Scene &scene)
    {
      std::vector<unsigned int> cells;
      for (unsigned int c = std::max(1u, scene.discretisation.graded_layers); c <= most_cells / 2; c *= 2)
        cells.push_back(c);
      return cells;
    }

    /// Refuses, before any mesh is built, a band that even the largest mesh
    /// cannot hold: each of its modes needs a degree of freedom at least.
    void check_band_reachable(const BarModel &bar, const Scene &scene, const double top)
    {
      const unsigned int largest   = candidate_cells(scene).back();
      const double       modes     = continuum_modes_below(bar, top);
      const double most_dofs = double(largest) * scene.discretisation.degree;
      if (modes <= most_dofs)
        return;
      std::ostringstream s;
      s.precision(3);
      s << "parameter 'Discretisation/Cells' = 0 chooses the cells for the band [0, M Omega max] = [0, " << top
        << "], which holds about " << modes << " modes of the bar (w_j ~ (j - 1/2) pi c / L), more than the " << most_dofs
        << " degrees of freedom of the largest mesh it tries (" << largest << " cells of FE_Q("
        << scene.discretisation.degree << ")): lower Harmonic balance/Harmonics or Continuation/Omega max, or set Cells";
      throw InputError(s.str());
    }

    /// A stop signal ends the search: no mesh is chosen yet, nothing computed.
    void answer_stop()
    {
      if (const int signal = point_stop_signal(); signal != 0)
        throw StopRequested(signal, "the search for the band's cells (Discretisation/Cells = 0)");
    }
  } // namespace

  BandCells cells_for_band(const BarModel &bar, const Scene &scene)
  {
    BandCells choice;
    // The automatic range needs mode j's clamped-clamped frequency: a mesh
    // with fewer modes than Mode + 1 is not a candidate.
    const unsigned int least_dofs = scene.continuation.mode + 1;
    Progress           progress("cells for the band", scene.output.progress_every);
    for (const unsigned int cells : candidate_cells(scene))
      {
        if (cells * scene.discretisation.degree < least_dofs)
          continue;
        answer_stop();
        Scene candidate                = scene;
        candidate.discretisation.cells = cells;
        const Discretisation coarse(bar, candidate.discretisation);
        if (candidate.continuation.omega_max == 0 && (candidate.output.backbone || candidate.output.fields()))
          resolve_automatic_range(candidate.continuation, candidate.contact, candidate.output.fields_at, coarse);
        const double top = candidate.receptance_band();
        if (top <= 0)
          throw InputError("parameter 'Discretisation/Cells' = 0 is out of range: chooses the cells for the band "
                           "[0, M Omega max] of a backbone, a field or receptance.csv, and the scene asks for none; "
                           "allowed an integer in [1, 1000000]");
        check_band_reachable(bar, scene, top);
        answer_stop();
        const Discretisation fine(coarse, coarse.fe().degree, 1);
        choice.cells     = cells;
        choice.agreement = band_agreement(coarse, fine, top);
        choice.tried.push_back(cells);
        if (choice.agreement.error <= band_tolerance)
          return choice;
        progress.update([&] {
          std::ostringstream s;
          s.precision(2);
          s << cells << " cells of FE_Q(" << scene.discretisation.degree << ") agree with twice the cells to "
            << choice.agreement.error << " up to " << significant(top, 4) << " (" << choice.agreement.modes
            << " modes; wanted " << band_tolerance << "): trying " << 2 * cells;
          return s.str();
        });
      }
    answer_stop();
    std::ostringstream s;
    s << "Discretisation/Cells = 0: no mesh up to " << choice.cells << " cells of FE_Q("
      << scene.discretisation.degree << ") resolves the band to " << band_tolerance
      << " (its eigenfrequencies agree to " << choice.agreement.error << "): set Cells, or raise Degree";
    throw NumericalError(s.str());
  }

  std::string describe(const BandCells &choice, const unsigned int degree)
  {
    std::ostringstream s;
    s.precision(2);
    s << "Discretisation/Cells = 0: " << choice.cells << " cells of FE_Q(" << degree
      << "): its eigenfrequencies up to " << significant(choice.agreement.top, 4) << " ("
      << counted(choice.agreement.modes, "mode") << ") agree with twice the cells' to " << choice.agreement.error
      << ", within " << band_tolerance << " (tried";
    for (const unsigned int c : choice.tried)
      s << ' ' << c;
    s << ')';
    return s.str();
  }
} // namespace nsm
