#include <nsm/model/adaptive_refinement.h>
#include <nsm/base/progress.h>
#include <nsm/model/receptance.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace nsm
{
  std::vector<double> band_frequencies(const double band_max, const unsigned int count)
  {
    std::vector<double> band;
    for (unsigned int i = 0; i < count; ++i)
      band.push_back(band_max * (i + 0.5) / count);
    return band;
  }

  std::vector<std::string> refine_adaptively(Discretisation              &d,
                                             const DiscretisationParameters &params,
                                             const double                 band_max,
                                             Progress                    *progress)
  {
    const std::vector<double> band = band_frequencies(band_max);
    const ReceptanceParameters   direct{ReceptanceMethod::direct, 0};
    std::vector<std::string>  notes;
    for (unsigned int step = 0;; ++step)
      {
        const Discretisation  richer(d, d.fe().degree + 1);
        const Receptance      coarse(d, direct, 0.0), fine(richer, direct, 0.0);
        double                error = 0, scale = 0;
        dealii::Vector<float> indicators(d.n_cells());
        for (const double w : band)
          {
            const dealii::Vector<double> h      = coarse.field(w);
            const double                 g_fine = fine(w).gamma;
            error = std::max(error, std::abs(h[d.contact_dof()] - g_fine));
            scale = std::max(scale, std::abs(g_fine));
            dealii::Vector<float> eta = d.kelly_indicators(h);
            eta /= std::max(double(eta.l1_norm()), 1e-300);
            indicators += eta;
          }
        std::ostringstream note;
        note << "adaptive step " << step << ": " << d.n_dofs()
             << " DoFs, estimated relative error of gamma over [0, " << band_max
             << "]: " << error / scale;
        notes.push_back(note.str());
        if (progress)
          progress->update([&] { return note.str(); });
        if (error <= params.adaptive_tolerance * scale || step == params.adaptive_steps)
          return notes;
        if (d.min_cell_size() / 2 < params.smallest_cell() * d.bar().length())
          {
            notes.push_back("adaptive refinement stops: halving the smallest cell would put "
                            "the round-off floor eps p^2 L / h_min above Discretisation/Round-off "
                            "limit");
            return notes;
          }
        d.refine(indicators, params.adaptive_fraction);
      }
  }
} // namespace nsm
