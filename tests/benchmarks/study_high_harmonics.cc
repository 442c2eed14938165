// Study (not a test): why the seed bar's branch is lost at M = 160 (near
// Omega = 1.964, doc/accuracy-and-cost.md) when its leaps have only their own
// guesses, and why the branch with half the harmonics carries it. Two measures:
//  1. how fragmented the contact is on the main branch at M = 40, 80, 160:
//     the sign changes of q = lambda - alpha g over a period, recomputed here
//     from the physical Fourier coefficients on a fine grid (their share of
//     q > 0 must equal the contact fraction the code measures);
//  2. whether Newton at M = 160 converges from the M = 80 main points beyond
//     the fold where M = 160 is lost, padded with zero harmonics: the branch
//     exists there at M = 80 and moves little from M = 80 to 160 where both
//     are found, so this is as good a guess as any leap could make.
#include <nsm/base/threads.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include "hb_model.h"

namespace
{
  struct ContactShape
  {
    int    sign_changes;
    double share; ///< of the period with q > 0
  };

  /// q on a grid over the period; the cosine basis is even, so half a period
  /// holds half the sign changes.
  ContactShape contact_shape(const nsm::Scene &scene, const nsm::FourierCoefficients &c)
  {
    const double        alpha = scene.contact.alpha;
    std::vector<double> v(c.force.size());
    for (std::size_t i = 0; i < v.size(); ++i)
      v[i] = c.force[i] + alpha * c.displacement[i];
    v[0] -= alpha * scene.contact.gap;
    const int samples = 40000;
    int       changes = 0, positive = 0;
    bool      before  = false;
    for (int s = 0; s <= samples; ++s)
      {
        double q = v[0];
        for (std::size_t i = 1; i < v.size(); ++i)
          q += v[i] * std::cos(c.order[i] * M_PI * s / samples);
        changes += s > 0 && (q > 0) != before;
        positive += q > 0;
        before = q > 0;
      }
    return {2 * changes, positive / (samples + 1.0)};
  }

  nsm::Scene seed(const unsigned int harmonics)
  {
    nsm::Scene scene = testing_helpers::seed_scene(nsm::ForceSign::physical, 1.5, 2.2);
    // FE_Q(10) x 20 resolves gamma up to k W = 320 (the study's mesh, tests/studies/ended.prm).
    scene.discretisation.cells       = 20;
    scene.harmonic_balance.harmonics = harmonics;
    scene.continuation.leap_from_fewer_harmonics = false;
    return scene;
  }
  /// Newton at M = `to` from the main points of `coarse` (M = `from`) beyond
  /// `beyond`, padded with zero harmonics; then, where it fails, as a leap's
  /// second try (branch_context.cc): line search and twice the iterations.
  void padded_start(const nsm::Backbone &coarse, const unsigned int from, const unsigned int to, const double beyond)
  {
    testing_helpers::HbModel    model(seed(to));
    nsm::HarmonicBalanceParameters leap = model.scene.harmonic_balance;
    leap.line_search                 = "Polynomial";
    leap.max_iterations = leap.iterations() * 2;
    nsm::NewtonSolver   newton(model.hb, model.scene.harmonic_balance), leap_newton(model.hb, leap);
    unsigned int        tried = 0, plain = 0, either = 0;
    std::vector<double> moved;
    for (const nsm::BackbonePoint &p : coarse.points)
      {
        if (p.branch != nsm::Branch::main || p.omega <= beyond)
          continue;
        ++tried;
        std::vector<double> guess(model.hb.n_unknowns(), 0.0);
        std::copy(p.x.begin(), p.x.end(), guess.begin());
        nsm::NewtonResult r = newton.solve(p.omega, guess);
        plain += r.converged;
        if (!r.converged)
          r = leap_newton.solve(p.omega, guess);
        if (!r.converged)
          continue;
        ++either;
        model.hb.set_omega(p.omega);
        moved.push_back(std::abs(model.hb.measure(r.x).energy / p.measures.energy - 1));
      }
    std::sort(moved.begin(), moved.end());
    std::printf("| %u to %u | %u | %u | %u (%.0f %%) | %.2e | %.2e |\n", from, to, tried, plain, either,
                100.0 * either / tried, moved.empty() ? NAN : moved[moved.size() / 2], moved.empty() ? NAN : moved.back());
  }
} // namespace

int main()
{
  nsm::use_one_thread(); // as nsm-bar: the same results
  std::printf("seed bar, FE_Q(10) x 20, modal, exact integration, grazing to 2.2, Energy max 1e-3\n\n");
  std::printf("| M | points | main points | Omega reached | sign changes of q per period on main points: median | max "
              "| share with more than 2 | largest |share(q > 0) - contact fraction| |\n|---|---|---|---|---|---|---|---|\n");
  std::map<unsigned int, nsm::Backbone> runs;
  for (const unsigned int harmonics : {40u, 80u, 160u})
    {
      testing_helpers::HbModel model(seed(harmonics));
      const nsm::Backbone     &b = runs[harmonics] = model.backbone();
      std::vector<int>         changes;
      double                   mismatch = 0;
      for (const nsm::BackbonePoint &p : b.points)
        if (p.branch == nsm::Branch::main)
          {
            model.hb.set_omega(p.omega);
            const ContactShape shape = contact_shape(model.scene, model.hb.coefficients(p.x));
            changes.push_back(shape.sign_changes);
            mismatch = std::max(mismatch, std::abs(shape.share - p.measures.contact_fraction));
          }
      std::sort(changes.begin(), changes.end());
      const double reached = *b.omega_reached(1);
      std::printf("| %u | %zu | %zu | %.6f | %d | %d | %.0f %% | %.1e |\n", harmonics, b.points.size(), changes.size(),
                  reached, changes[changes.size() / 2], changes.back(),
                  100.0 * std::count_if(changes.begin(), changes.end(), [](int n) { return n > 2; }) / changes.size(),
                  mismatch);
      std::fflush(stdout);
    }
  const double lost160 = *runs[160].omega_reached(1);

  std::printf("\nNewton at M from the main points of M / 2 beyond Omega = %.6f (where M = 160 is lost), padded with "
              "zeros\n\n| M / 2 to M | points | converge | also with the leap's second try | energy moved: median "
              "| largest |\n|---|---|---|---|---|---|\n", lost160);
  for (const auto &[from, to] : {std::pair{40u, 80u}, std::pair{80u, 160u}})
    padded_start(runs[from], from, to, lost160);
}
