#include <nsm/base/errors.h>
#include <nsm/base/dense_lu.h>
#include <nsm/base/vector_norm.h>
#include <nsm/verification/forced_floquet.h>
#include <nsm/verification/forced_modal_steps.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>

namespace nsm
{
  namespace
  {
    /// |P(z) - z| / |z|.
    double relative_defect(const std::vector<double> &image, const std::vector<double> &z)
    {
      std::vector<double> r(z.size());
      for (std::size_t i = 0; i < z.size(); ++i)
        r[i] = image[i] - z[i];
      return two_norm(r) / std::max(two_norm(z), 1e-300);
    }

    /// One period from the model's state: P(z), and its Jacobian (column-
    /// major, 2N x 2N, on the modes' q and v).
    std::vector<double> period(ForcedModalSteps &model, const unsigned int steps, std::vector<double> &jacobian)
    {
      const unsigned int                     n = model.modes();
      std::vector<ForcedModalSteps::Tangent> tangents;
      for (const bool velocity : {false, true})
        for (unsigned int j = 0; j < n; ++j)
          tangents.push_back(model.start_tangent(j, velocity));
      for (unsigned int s = 0; s < steps; ++s)
        model.step(&tangents);
      jacobian.assign(std::size_t(4) * n * n, 0.0);
      for (unsigned int c = 0; c < 2 * n; ++c)
        for (unsigned int j = 0; j < n; ++j)
          {
            jacobian[std::size_t(c) * 2 * n + j]     = tangents[c].q[j];
            jacobian[std::size_t(c) * 2 * n + n + j] = tangents[c].v[j];
          }
      return model.state();
    }
  } // namespace

  unsigned int FloquetMultipliers::beyond_plus_one() const
  {
    return std::count_if(values.begin(), values.end(),
                         [](const std::complex<double> &m) { return m.imag() == 0 && m.real() > 1; });
  }

  std::string FloquetMultipliers::instability() const
  {
    if (values.empty() || std::abs(values.front()) <= 1)
      return "";
    const std::complex<double> m = values.front();
    if (m.imag() != 0)
      return "Neimark-Sacker";
    return m.real() > 0 ? "fold" : "period doubling";
  }

  namespace
  {
    /// Newton's method on z -> P(z) from z (shooting; see the header): true
    /// with the orbit in z, the period's Jacobian there in `jacobian` and
    /// the Newton steps and residual in `result`; false where it stalls.
    bool shoot(ForcedModalSteps &model, const unsigned int steps, std::vector<double> &z,
               std::vector<double> &jacobian, FloquetMultipliers &result)
    {
      const int n = 2 * model.modes();
      // |P(z) - z| / |z| from one period without tangents.
      const auto defect = [&](const std::vector<double> &start) {
        model.restart(start);
        for (unsigned int s = 0; s < steps; ++s)
          model.step();
        return relative_defect(model.state(), start);
      };
      model.restart(z);
      for (unsigned int k = 0;; ++k)
        {
          const std::vector<double> image = period(model, steps, jacobian);
          result.residual                 = relative_defect(image, z);
          if (result.residual <= floquet_constants::orbit_tolerance)
            {
              result.newton_steps = k;
              return true;
            }
          if (k == floquet_constants::newton_steps)
            return false;
          // (I - Phi) dz = P(z) - z, the step halved until the defect falls
          // (the harmonic balance's start is a few per cent from the orbit in
          // the high modes, and a full first step overshoots).
          std::vector<double> a = jacobian;
          for (int i = 0; i < n; ++i)
            {
              for (int j = 0; j < n; ++j)
                a[std::size_t(j) * n + i] = -a[std::size_t(j) * n + i];
              a[std::size_t(i) * n + i] += 1;
            }
          std::vector<double> r(n);
          for (int i = 0; i < n; ++i)
            r[i] = image[i] - z[i];
          std::vector<int> pivots(n);
          if (!lu_factor(n, a.data(), pivots.data()))
            return false;
          lu_solve(n, a.data(), pivots.data(), r.data());
          bool accepted = false;
          for (double share = 1; share >= floquet_constants::least_share && !accepted; share /= 2)
            {
              std::vector<double> trial = z;
              for (int i = 0; i < n; ++i)
                trial[i] += share * r[i];
              if (defect(trial) < result.residual)
                {
                  z        = trial;
                  accepted = true;
                }
            }
          if (!accepted)
            return false;
          model.restart(z);
        }
    }
  } // namespace

  FloquetMultipliers floquet_multipliers(const ForcedHarmonicBalance &hb, const std::vector<double> &x,
                                         const unsigned int steps, const std::vector<double> &settled)
  {
    if (hb.law().rigid())
      throw InputError("Floquet multipliers need the compliant wall (Contact/Wall = compliant): the rigid wall's "
                       "impacts are not continuous in the state");
    ForcedModalSteps    model(hb, x, steps);
    const int           n = 2 * model.modes();
    std::vector<double> z = model.state(), jacobian;
    FloquetMultipliers  result;
    if (!shoot(model, steps, z, jacobian, result))
      {
        z = settled;
        if (z.size() != std::size_t(n) || !shoot(model, steps, z, jacobian, result))
          return {};
        result.from_settled = true;
      }
    dealii::LAPACKFullMatrix<double> monodromy(n, n);
    for (int c = 0; c < n; ++c)
      for (int i = 0; i < n; ++i)
        monodromy(i, c) = jacobian[std::size_t(c) * n + i];
    monodromy.compute_eigenvalues();
    for (int i = 0; i < n; ++i)
      result.values.push_back(monodromy.eigenvalue(i));
    std::sort(result.values.begin(), result.values.end(),
              [](const std::complex<double> &a, const std::complex<double> &b) { return std::abs(a) > std::abs(b); });
    return result;
  }
} // namespace nsm
