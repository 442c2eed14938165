// The uniform bar's periodic orbit on FE meshes of falling h, shot from the
// exact tent interpolated on each mesh (least-norm Newton steps select the
// member of the FE model's orbits nearest the tent, periodic_orbit.h), against
// the tent's energy g0^2 / (2 (T - 3)^2) and contact fraction (4 - T) / T.
//
//   study_uniform_orbit [degree [periods [cells...]]]
//
// periods: a comma-separated list (default 3.2,3.5,3.8); cells: default
// 25 50 100 200. Prints one CSV row per period and mesh.
#include <nsm/base/threads.h>
#include <nsm/model/bar_model.h>
#include <nsm/model/discretisation.h>
#include <nsm/verification/periodic_orbit.h>
#include <nsm/verification/time_verification.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "exact_bar.h"
#include "scene_helpers.h"

namespace
{
  constexpr double g0 = 1e-3;

  std::vector<double> parse_list(const std::string &text)
  {
    std::vector<double> list;
    std::size_t         begin = 0;
    for (std::size_t end; (end = text.find(',', begin)) != std::string::npos; begin = end + 1)
      list.push_back(std::stod(text.substr(begin, end - begin)));
    list.push_back(std::stod(text.substr(begin)));
    return list;
  }

  /// The tent of `mode` at the support points of `discretisation`.
  dealii::Vector<double> tent_on(const nsm::Discretisation &discretisation, const exact::UniformMode &mode)
  {
    const auto             x = discretisation.support_points();
    dealii::Vector<double> tent(x.size());
    for (unsigned int i = 0; i < x.size(); ++i)
      tent[i] = x[i] <= mode.x_peak ? mode.peak * x[i] / mode.x_peak
                                    : mode.peak + (g0 - mode.peak) * (x[i] - mode.x_peak) / (1 - mode.x_peak);
    return tent;
  }
  /// The submatrix of `m` on `dofs`, dense.
  dealii::LAPACKFullMatrix<double> restricted(const dealii::SparseMatrix<double> &m,
                                              const std::vector<unsigned int>    &dofs)
  {
    dealii::LAPACKFullMatrix<double> r(dofs.size(), dofs.size());
    for (std::size_t i = 0; i < dofs.size(); ++i)
      for (std::size_t j = 0; j < dofs.size(); ++j)
        r(i, j) = m.el(dofs[i], dofs[j]);
    return r;
  }

  /// The energy of a state at rest on the wall (u_N = g0) above its static
  /// part, split at the first mode of the wall's problem whose FE frequency
  /// is more than `share` above the continuum's j pi: {resolved, unresolved}.
  struct ModalSplit
  {
    dealii::LAPACKFullMatrix<double>    mass;
    std::vector<dealii::Vector<double>> modes;  ///< mass-normalised, by rising frequency (LAPACK's order)
    std::vector<double>                 lambda; ///< their eigenvalues w^2
    std::vector<unsigned int>           dofs;
    dealii::Vector<double>              static_shape; ///< K_II u = -K_IN g0 on dofs
    unsigned int                        resolved = 0; ///< modes within the share

    ModalSplit(const nsm::Discretisation &d, const double share)
    {
      for (unsigned int i = 0; i < d.n_dofs(); ++i)
        if (i != d.contact_dof() && i != d.clamped_dof())
          dofs.push_back(i);
      mass                              = restricted(nsm::redistributed_mass(d), dofs);
      dealii::LAPACKFullMatrix<double> k = restricted(d.stiffness(), dofs), m = mass, factor = k;
      modes.resize(dofs.size(), dealii::Vector<double>(dofs.size()));
      k.compute_generalized_eigenvalues_symmetric(m, modes);
      for (unsigned int j = 0; j < dofs.size(); ++j)
        lambda.push_back(k.eigenvalue(j).real());
      while (resolved < lambda.size() && std::sqrt(lambda[resolved]) <= (1 + share) * (resolved + 1) * M_PI)
        ++resolved;
      static_shape.reinit(dofs.size());
      for (std::size_t i = 0; i < dofs.size(); ++i)
        static_shape[i] = -d.stiffness().el(dofs[i], d.contact_dof()) * g0;
      factor.compute_lu_factorization();
      factor.solve(static_shape);
    }

    /// {energy in the resolved modes, in the others} of nodal u at rest,
    /// about the static shape of the wall's problem.
    std::pair<double, double> split(const dealii::Vector<double> &u) const
    {
      const std::size_t      n = dofs.size();
      dealii::Vector<double> w(n), mw(n);
      for (std::size_t i = 0; i < n; ++i)
        w[i] = u[dofs[i]] - static_shape[i];
      mass.vmult(mw, w);
      std::pair<double, double> e{0, 0};
      for (std::size_t j = 0; j < n; ++j)
        {
          const double a = modes[j] * mw;
          (j < resolved ? e.first : e.second) += lambda[j] * a * a / 2;
        }
      return e;
    }
  };
} // namespace

int main(int argc, char **argv)
{
  nsm::use_one_thread();
  const unsigned int        degree  = argc > 1 ? std::atoi(argv[1]) : 1;
  const std::vector<double> periods = parse_list(argc > 2 ? argv[2] : "3.2,3.5,3.8");
  std::vector<unsigned int> cells;
  for (int a = 3; a < argc; ++a)
    cells.push_back(std::atoi(argv[a]));
  if (cells.empty())
    cells = {25, 50, 100, 200};

  std::printf("period,degree,cells,dofs,converged,newton_steps,energy,tent_energy,energy_error,"
              "contact_fraction,exact_fraction,fraction_error,isolation,shape_error,resolved_modes,modes,resolved_energy_error,unresolved_share_orbit,unresolved_share_tent,seconds\n");
  for (const double period : periods)
    for (const unsigned int n : cells)
      {
        const exact::UniformMode  mode(period, g0);
        const nsm::Scene          scene = testing_helpers::bar_scene("1", degree, n);
        const nsm::BarModel       bar(scene.bar);
        const nsm::Discretisation discretisation(bar, scene.discretisation);
        const auto                start = std::chrono::steady_clock::now();
        const dealii::Vector<double> tent = tent_on(discretisation, mode);
        const nsm::PeriodicOrbit     orbit =
          nsm::find_periodic_orbit(discretisation, testing_helpers::wall_at(g0), 2 * M_PI / period, tent,
                                   {1e-10, 1e-4, false});
        const ModalSplit modal(discretisation, 0.01);
        const auto       mine  = modal.split(orbit.displacement);
        const auto       exact = modal.split(tent);
        double shape = 0;
        for (unsigned int i = 0; i < tent.size(); ++i)
          shape = std::max(shape, std::abs(orbit.displacement[i] - tent[i]) / mode.peak);
        const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double fraction = (4 - period) / period;
        std::printf("%.4f,%u,%u,%u,%d,%u,%.10e,%.10e,%.3e,%.6f,%.6f,%.3e,%.3e,%.3e,%u,%zu,%.3e,%.3e,%.3e,%.2f\n", period, degree, n,
                    discretisation.n_dofs(), orbit.converged, orbit.newton_steps, orbit.energy, mode.energy,
                    orbit.energy / mode.energy - 1, orbit.contact_fraction, fraction,
                    orbit.contact_fraction - fraction, orbit.isolation, shape, modal.resolved, modal.dofs.size(),
                    mine.first / exact.first - 1, mine.second / (mine.first + mine.second),
                    exact.second / (exact.first + exact.second), seconds);
        std::fflush(stdout);
      }
  return 0;
}
