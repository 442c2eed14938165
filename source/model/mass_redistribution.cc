#include <nsm/base/errors.h>
#include <nsm/model/mass_redistribution.h>

#include <cmath>

namespace nsm
{
  void redistribute_contact_mass(dealii::SparseMatrix<double> &mass, const unsigned int contact)
  {
    double removed = 0, coupling = 0;
    for (auto e = mass.begin(contact); e != mass.end(contact); ++e)
      {
        removed += (e->column() == contact ? 1 : 2) * e->value();
        if (e->column() != contact)
          coupling += std::abs(e->value());
      }
    if (removed == 0)
      return; // already without inertia
    if (coupling == 0)
      throw InputError("parameter 'Discretisation/Contact mass' = redistributed is out of range: allowed only "
                       "with a DoF beside the contact DoF (Cells x Degree >= 2)");
    for (auto e = mass.begin(contact); e != mass.end(contact); ++e)
      if (e->column() != contact)
        mass.add(e->column(), e->column(), removed * std::abs(e->value()) / coupling);
    for (auto e = mass.begin(contact); e != mass.end(contact); ++e)
      {
        mass.set(e->column(), contact, 0.0);
        e->value() = 0;
      }
  }
} // namespace nsm
