#include <nsm/base/errors.h>
#include <nsm/base/text.h>
#include <nsm/model/automatic_range.h>
#include <nsm/model/banded_pencil.h>
#include <nsm/model/near_modes.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// ModeFrequencies::held.
    double held_frequency(const Discretisation &d, const unsigned int mode, const ContactParameters &contact,
                          bool &on_spring)
    {
      on_spring = contact.wall == Wall::compliant && contact.sign == ForceSign::physical;
      if (!on_spring)
        {
          const BandedPencil held(d, EndCondition::clamped_clamped);
          if (int(mode) > held.finite)
            throw InputError("parameter 'Discretisation/Cells' = " + std::to_string(d.n_cells()) +
                             " is out of range: the automatic range (Continuation/Omega max = 0 or Energy max = 0) "
                             "reads mode " + std::to_string(mode) + " of the bar held at both ends, which a mesh of "
                             "Cells x Degree = " + std::to_string(d.n_cells()) + " x " +
                             std::to_string(d.fe().degree) + " does not have: allowed Cells x Degree >= Mode + 1 = " +
                             std::to_string(mode + 1) + ", or set Omega max and Energy max");
          return std::sqrt(lowest_eigenvalues(held, mode)[mode - 1]);
        }
      BandedPencil spring(d, EndCondition::clamped_free);
      spring.entry(spring.k, spring.contact_row, spring.contact_row) += contact.stiffness;
      return std::sqrt(lowest_eigenvalues(spring, mode)[mode - 1]);
    }
  } // namespace

  ModeFrequencies mode_frequencies(const Discretisation &d, const unsigned int mode, const ContactParameters &contact)
  {
    // The lowest modes alone (near_modes.h): the whole spectrum of the
    // paper's 4000-cell mesh costs more than the rest of its run.
    const BandedPencil free_pencil(d, EndCondition::clamped_free);
    // An adaptive mesh is known only now: Mode is checked against it here.
    if (mode > unsigned(free_pencil.finite))
      throw InputError("parameter 'Continuation/Mode' = " + std::to_string(mode) +
                       " is out of range: allowed an integer in [1, " + std::to_string(free_pencil.finite) +
                       "] (the modes of the mesh, refined" +
                       (free_pencil.finite < free_pencil.n ? ", without inertia at the contact DoF)" : ")"));
    const int                 count  = std::min<int>(mode + 1, free_pencil.finite);
    const std::vector<double> lowest = lowest_eigenvalues(free_pencil, count);
    // A bound between mode j and the next (or above the last mode).
    const double    upper = count > int(mode) ? (lowest[mode - 1] + lowest[mode]) / 2 : 2 * lowest[mode - 1];
    const ModalData free  = modes_below(free_pencil, upper);
    ModeFrequencies f;
    const double    w2 = free.eigenvalues[mode - 1];
    f.free             = std::sqrt(w2);
    f.held             = held_frequency(d, mode, contact, f.on_spring);
    f.bilinear         = 2 * f.free * f.held / (f.free + f.held);
    f.grazing_energy   = w2 * contact.gap * contact.gap / (2 * free.contact_residues[mode - 1]);
    return f;
  }

  namespace
  {
    std::string number(const double value) { return significant(value, 10); }
  } // namespace

  std::vector<std::string> resolve_automatic_range(ContinuationParameters &c, const ContactParameters &contact,
                                                   const std::vector<double> &fields_at, const Discretisation &d)
  {
    if (c.omega_max > 0 && c.energy_max > 0)
      return {};
    const ModeFrequencies    f = mode_frequencies(d, c.mode, contact);
    std::vector<std::string> notes;
    if (c.omega_max == 0)
      {
        c.omega_max = f.free + automatic_range_share * (f.bilinear - f.free);
        notes.push_back("Continuation/Omega max = 0: " + number(c.omega_max) + ", from the spectrum (w_" +
                        std::to_string(c.mode) + " = " + number(f.free) + " clamped-free, " + number(f.held) +
                        (f.on_spring ? " on the wall's spring" : " clamped-clamped") + ", bilinear limit " +
                        number(f.bilinear) + ")");
        if (contact.wall == Wall::compliant && contact.sign == ForceSign::physical &&
            c.omega_max <= f.free * (1 + c.grazing_offset))
          throw InputError("parameter 'Contact/Wall stiffness' = " + number(contact.stiffness) +
                           " is out of range: the wall's spring holds the bar at w = " + number(f.held) +
                           ", so little above w_" + std::to_string(c.mode) + " = " + number(f.free) +
                           " that the automatic range (Continuation/Omega max = 0) ends at " + number(c.omega_max) +
                           ", before the branch leaves grazing at " + number(f.free * (1 + c.grazing_offset)) +
                           ": allowed a stiffer wall, or set Continuation/Omega max above that");
        if (!(c.omega_min < c.omega_max))
          throw InputError("parameter 'Continuation/Omega min' = " + number(c.omega_min) +
                           " is out of range: allowed below the automatic Omega max = " + number(c.omega_max) +
                           " (Continuation/Omega max = 0); set Omega max");
        for (const double w : fields_at)
          if (w < c.omega_min || w > c.omega_max)
            throw InputError("parameter 'Output/Fields at' = " + number(w) +
                             " is out of range: allowed frequencies in [Omega min, Omega max] = [" +
                             number(c.omega_min) + ", " + number(c.omega_max) + "] (automatic Omega max)");
      }
    if (c.energy_max == 0)
      {
        c.energy_max = c.energy_max_over_grazing * f.grazing_energy;
        notes.push_back("Continuation/Energy max = 0: " + number(c.energy_max) + " = Energy max over grazing = " +
                        number(c.energy_max_over_grazing) + " times E_g = " + number(f.grazing_energy));
      }
    return notes;
  }
} // namespace nsm
