#include <nsm/harmonic_balance/solution_measures.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace nsm
{
  SolutionMeasures::SolutionMeasures(const unsigned int harmonics)
    : harmonics_(harmonics)
    , energy_basis_(harmonic_basis(2 * harmonics, true))
    , energy_samples_(energy_basis_, 4 * (2 * harmonics + 1))
  {}

  double SolutionMeasures::mean_wall_energy(const PhasedSolution &solution, const ContactLaw &law) const
  {
    // The harmonic balance's force is the projection of k max(u - g0, 0) on
    // the basis, which holds u - g0: the mean of lambda (u - g0) / 2 is the
    // mean of k max(u - g0, 0)^2 / 2, by Parseval (exactly with the exact
    // rule; with the sampled one, to its quadrature).
    double mean = 0;
    for (unsigned int i = 0; i < solution.functions.size(); ++i)
      {
        const HarmonicPhase &p = solution.phases[solution.functions.order[i]];
        const double         c = solution.scale * solution.x[i];
        const double         u = law.displacement_coefficient(c, p.sin);
        mean += solution.functions.order[i] == 0 ? c * p.cos * (u - law.gap()) : c * p.cos * u / 2;
      }
    return mean / 2;
  }

  void SolutionMeasures::add_wall_energy(const PhasedSolution &solution, const ContactLaw &law,
                                         std::vector<double> &e) const
  {
    // u(L, tau) on the energy's basis (slot 2m - 1: sin m tau, 2m: cos m tau).
    const TrigonometricBasis &functions = solution.functions;
    std::vector<double>       coefficients(energy_basis_.size(), 0.0), u;
    for (unsigned int i = 0; i < functions.size(); ++i)
      {
        const unsigned int m    = functions.order[i];
        const unsigned int slot = m == 0 ? 0 : (functions.sine[i] ? 2 * m - 1 : 2 * m);
        coefficients[slot] +=
          law.displacement_coefficient(solution.scale * solution.x[i], solution.phases[m].sin);
      }
    energy_samples_(coefficients, u);
    for (std::size_t t = 0; t < e.size(); ++t)
      e[t] += law.stored_energy(u[t]);
  }

  void SolutionMeasures::energy(const PhasedSolution &solution, const ContactLaw &law,
                                PeriodicSolutionMeasures &result) const
  {
    const TrigonometricBasis  &functions = solution.functions;
    const std::vector<double> &x         = solution.x;
    const unsigned int         n = functions.size(), top = 2 * harmonics_ + 1;
    const double               f2 = solution.scale * solution.scale, w2 = solution.omega * solution.omega;

    // Energy over the period as a trigonometric polynomial: with h_k the
    // receptance field, h_k^T M h_l = (gamma_k - gamma_l) / (w_k^2 - w_l^2),
    // which in the angle variables reads sin(theta_k - theta_l) / (...).
    std::vector<double> ec(top, 0.0), es(top, 0.0);
    const auto add = [&](double weight) {
      return [&, weight](bool sine, int m, double c) { (sine ? es : ec)[m] += weight * c; };
    };
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        {
          const HarmonicPhase &p = solution.phases[functions.order[i]], &q = solution.phases[functions.order[j]];
          const double         cc = x[i] * x[j] * f2;
          double               mass, stiffness;
          if (functions.order[i] == functions.order[j])
            {
              mass      = p.dtheta_domega2;
              stiffness = p.sin * p.cos + p.omega2 * p.dtheta_domega2;
            }
          else
            {
              const double d = p.omega2 - q.omega2;
              mass      = (p.sin * q.cos - p.cos * q.sin) / d;
              stiffness = (p.omega2 * p.sin * q.cos - q.omega2 * p.cos * q.sin) / d;
            }
          // strain: phi_i phi_j; kinetic: W^2 phi_i' phi_j' (derivatives in tau).
          product_terms(functions.sine[i], functions.order[i], functions.sine[j], functions.order[j],
                        add(0.5 * cc * stiffness));
          const double ki = functions.order[i], kj = functions.order[j];
          const double sign_i = functions.sine[i] ? 1.0 : -1.0, sign_j = functions.sine[j] ? 1.0 : -1.0;
          product_terms(!functions.sine[i], functions.order[i], !functions.sine[j], functions.order[j],
                        add(0.5 * cc * w2 * mass * ki * kj * sign_i * sign_j));
        }

    // The full basis of degree 2M orders its coefficients 1, then sin and
    // cos of each m.
    std::vector<double> coefficients(energy_basis_.size()), e;
    coefficients[0] = ec[0];
    for (unsigned int m = 1; m < top; ++m)
      coefficients[2 * m - 1] = es[m], coefficients[2 * m] = ec[m];
    energy_samples_(coefficients, e);
    // The bar's mean energy is ec[0]; a compliant wall stores energy too.
    if (law.rigid())
      result.energy = ec[0];
    else
      {
        add_wall_energy(solution, law, e);
        result.energy = ec[0] + mean_wall_energy(solution, law);
      }
    const double e_min = *std::min_element(e.begin(), e.end());
    const double e_max = *std::max_element(e.begin(), e.end());
    result.energy_spread = (e_max - e_min) / result.energy;
  }

  unsigned int leading_harmonic(const TrigonometricBasis &functions, const std::vector<double> &coefficients)
  {
    std::vector<double> square(functions.size() + 1, 0.0);
    for (unsigned int i = 0; i < functions.size(); ++i)
      square[functions.order[i]] += coefficients[i] * coefficients[i];
    return std::max_element(square.begin() + 1, square.end()) - square.begin();
  }

  std::vector<double> SolutionMeasures::harmonic_energies(const PhasedSolution &solution) const
  {
    // a^2 (gamma + 2 w^2 gamma') / 4 per cosine or sine (a_0^2 gamma(0) / 2),
    // in the angle variables a^2 gamma = c^2 sin cos, a^2 gamma' = c^2 dtheta/dw^2.
    const TrigonometricBasis &functions = solution.functions;
    std::vector<double>       energies(harmonics_ + 1, 0.0);
    for (unsigned int i = 0; i < functions.size(); ++i)
      {
        const HarmonicPhase &p = solution.phases[functions.order[i]];
        const double         c = solution.scale * solution.x[i];
        energies[functions.order[i]] +=
          c * c * (p.sin * p.cos + 2 * p.omega2 * p.dtheta_domega2) / (functions.order[i] == 0 ? 2.0 : 4.0);
      }
    return energies;
  }

  void SolutionMeasures::force_and_gap(const PhasedSolution &solution, const ActiveSet &samples,
                                       const ContactLaw &law, PeriodicSolutionMeasures &result) const
  {
    const TrigonometricBasis  &functions = solution.functions;
    const std::vector<double> &x         = solution.x;
    double lambda_max = -std::numeric_limits<double>::max(), lambda_min = -lambda_max;
    double gap_min = lambda_min, complementarity = 0, amplitude = 0;
    const unsigned int  n = functions.size(), count = samples.n_samples();
    std::vector<double> force(n), displacement(n), lambdas, us;
    for (unsigned int i = 0; i < n; ++i)
      {
        const HarmonicPhase &p = solution.phases[functions.order[i]];
        force[i]        = solution.scale * x[i] * p.cos;
        displacement[i] = law.displacement_coefficient(solution.scale * x[i], p.sin);
      }
    result.leading_harmonic = leading_harmonic(functions, displacement);
    samples.sample(force, lambdas);
    samples.sample(displacement, us);
    for (unsigned int t = 0; t < count; ++t)
      {
        const double lambda = lambdas[t], u = us[t];
        const double g = law.gap_at(u);
        lambda_max = std::max(lambda_max, lambda), lambda_min = std::min(lambda_min, lambda);
        gap_min = std::min(gap_min, g);
        amplitude = std::max(amplitude, std::abs(u));
        complementarity = std::max(complementarity, std::abs(lambda * g));
      }
    result.max_contact_force   = lambda_max;
    result.max_contact_displacement = amplitude;
    result.min_force           = lambda_min / lambda_max;
    result.min_gap             = gap_min / law.gap();
    result.max_complementarity = complementarity / (lambda_max * law.gap());
  }
} // namespace nsm
