#include <nsm/base/checkpoint_reader.h>
#include <nsm/verification/point_checkpoint.h>
#include <nsm/verification/refinement_checkpoint.h>

#include <limits>
#include <sstream>

namespace nsm
{
  namespace
  {
    constexpr const char *refinement_format_line = "nsm-bar refinement checkpoint 1";

    /// The measures a found orbit's line holds, in order (its multipliers
    /// are not written: only floquet_max reaches the output). O:
    /// PeriodicOrbit, const or not.
    template <typename O>
    auto measures(O &o)
    {
      return std::vector{&o.residual,          &o.energy,    &o.contact_fraction, &o.periodicity,
                         &o.max_contact_force, &o.isolation, &o.floquet_max};
    }
  } // namespace

  void write_refinement_checkpoint(std::ostream &out, const Backbone &backbone,
                                   const std::vector<std::optional<PeriodicOrbit>> &orbits,
                                   const OutputParameters &output)
  {
    out << refinement_format_line << "\nsettings " << output.refine_every << '\n';
    write_point_lines(out, backbone, orbits, [&](const PeriodicOrbit &o) {
      out << ' ' << o.converged << ' ' << o.newton_steps << ' ' << o.switches;
      for (const double *value : measures(o))
        out << ' ' << exact(*value);
      out << ' ' << o.displacement.size();
      for (const double u : o.displacement)
        out << ' ' << exact(u);
    });
  }

  std::vector<std::optional<PeriodicOrbit>> read_refinement_checkpoint(const std::string   &path,
                                                                       const Backbone      &backbone,
                                                                       const OutputParameters &output,
                                                                       const unsigned int   dofs)
  {
    std::vector<std::optional<PeriodicOrbit>> known(backbone.points.size());
    CheckpointReader                          reader(path);
    std::istringstream                        settings;
    if (!start_point_checkpoint(reader, refinement_format_line, settings))
      return known;
    constexpr std::size_t any = std::numeric_limits<unsigned int>::max();
    if (reader.count(settings, any) != output.refine_every)
      return known;
    read_point_lines(reader, backbone, [&](const std::size_t i, std::istringstream &row) {
      if (backbone.points[i].branch != Branch::main)
        reader.damaged("a main point of the resumed backbone expected");
      PeriodicOrbit o;
      o.converged    = reader.count(row, 1) == 1;
      o.newton_steps = reader.count(row, any);
      o.switches     = reader.count(row, any);
      for (double *value : measures(o))
        *value = reader.number(row);
      // Every shot orbit, found or not, holds its last displacement.
      const std::size_t n = reader.count(row, dofs);
      if (n != dofs)
        reader.damaged("a displacement of " + std::to_string(dofs) + " values expected");
      o.displacement.reinit(n);
      for (std::size_t j = 0; j < n; ++j)
        o.displacement[j] = reader.number(row);
      // floquet_max is 0 where no monodromy was computed (not found).
      o.stable = o.floquet_max > 0 && o.floquet_max <= 1 + output.stability_margin;
      known[i] = std::move(o);
    });
    return known;
  }
} // namespace nsm
