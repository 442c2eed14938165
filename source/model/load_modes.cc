#include <nsm/base/errors.h>
#include <nsm/model/load_modes.h>
#include <nsm/model/near_modes.h>
#include <nsm/model/shifted_factor.h>

#include <numeric>

namespace nsm
{
  namespace
  {
    double dot(const std::vector<double> &x, const std::vector<double> &y)
    {
      return std::inner_product(x.begin(), x.end(), y.begin(), 0.0);
    }
  } // namespace

  LoadModes load_modes(const Receptance &receptance, const dealii::Vector<double> &load)
  {
    const BandedPencil &p = receptance.pencil();
    std::vector<double> f(p.n);
    for (int i = 0; i < p.n; ++i)
      f[i] = load[p.dofs[i]];

    LoadModes        result;
    const ModalData &modes = receptance.modes();
    for (const double lambda : modes.eigenvalues)
      {
        const std::vector<double> phi = mode_shape(p, lambda);
        const double              b   = dot(phi, f);
        result.cross.push_back(phi[p.contact_row] * b);
        result.self.push_back(b * b);
      }

    // The static and first-order shares of every mode: e_N^T K^{-1} f =
    // sum_j s_j / w_j^2 and e_N^T K^{-1} M K^{-1} f = sum_j s_j / w_j^4 (f's
    // alike), less the summed modes'.
    ShiftedFactor<double> factor(p);
    factor.factor(0.0);
    if (factor.singular())
      throw NumericalError("the clamped-free stiffness is singular: no static response to the drive's load");
    std::vector<double> y = f, z(p.n, 0.0);
    z[p.contact_row]      = 1.0;
    factor.solve(y);
    factor.solve(z);
    const std::vector<double> my = p.mass_times(y);
    result.cross_far = {{y[p.contact_row], dot(z, my)}};
    result.self_far  = {{dot(f, y), dot(y, my)}};
    for (std::size_t j = 0; j < modes.eigenvalues.size(); ++j)
      {
        const double l = modes.eigenvalues[j];
        result.cross_far[0] -= result.cross[j] / l;
        result.cross_far[1] -= result.cross[j] / (l * l);
        result.self_far[0] -= result.self[j] / l;
        result.self_far[1] -= result.self[j] / (l * l);
      }
    return result;
  }

  std::unique_ptr<LoadModes> drive_modes(const Receptance &receptance, const Discretisation &discretisation,
                                         const ForcingShape shape)
  {
    if (shape == ForcingShape::tip)
      return nullptr;
    return std::make_unique<LoadModes>(load_modes(receptance, discretisation.unit_load()));
  }
} // namespace nsm
