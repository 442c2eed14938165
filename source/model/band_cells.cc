#include <nsm/base/errors.h>
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

  BandCells cells_for_band(const BarModel &bar, const Scene &scene)
  {
    BandCells choice;
    for (unsigned int cells = std::max(1u, scene.discretisation.graded_layers); cells <= most_cells / 2; cells *= 2)
      {
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
        const Discretisation fine(coarse, coarse.fe().degree, 1);
        choice.cells     = cells;
        choice.agreement = band_agreement(coarse, fine, top);
        choice.tried.push_back(cells);
        if (choice.agreement.error <= band_tolerance)
          return choice;
      }
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
      << choice.agreement.modes << " modes) agree with twice the cells' to " << choice.agreement.error
      << ", within " << band_tolerance << " (tried";
    for (const unsigned int c : choice.tried)
      s << ' ' << c;
    s << ')';
    return s.str();
  }
} // namespace nsm
