// Study: harmonic balance's truncation error alone. On one FE model (the seed
// bar, FE_Q(p) x cells, the contact DoF's mass redistributed, so that it is
// the model of the periodic orbits in time), HB at M harmonics should approach
// that model's periodic orbit as M grows. At `count` Omega evenly spaced
// between grazing and 2.2: the HB point on the main branch at exactly Omega
// with the smallest M (solve_on_branch, main points only), then the same
// solution followed in M: Newton at each next M from the last, its higher
// harmonics zero. From each, the orbit shot; HB's energy error against the
// orbit shot from the largest M's point. The cost at each M: a whole backbone
// to 2.2 (what a user pays for that M).
//   study_truncation [mesh [omegas [integration [mass [M...]]]]]
//   (defaults 10, 10, exact, redistributed, 20 40 80 160). mesh: a number of
//   cells of FE_Q(10), or DEGREExCELLS (4x7: FE_Q(4), 7 cells), either after
//   "uniform/" for the uniform bar (to Omega 1.85, Energy max 1e-5, its exact
//   tent in the column exact_energy) instead of the seed bar; omegas: a
//   count of evenly spaced Omega, or a list (2.1302,2.1581); integration:
//   exact or sampled; mass: redistributed or consistent, the latter HB's
//   model differing from the orbits'.
#include <nsm/base/csv.h>
#include <nsm/base/threads.h>
#include <nsm/verification/fields.h>
#include <nsm/verification/orbit_refinement.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "hb_model.h"

namespace
{
  constexpr double omega_end = 2.2;
  /// The uniform bar's tent lives for 3 < T < 4; uniform.prm ends at 1.85.
  constexpr double uniform_omega_end = 1.85;

  struct Row
  {
    bool                       on_main = false; ///< found (at the smallest M: and labelled main)
    double                     energy  = 0;
    std::optional<nsm::PeriodicOrbit> orbit;
  };

  struct Mesh
  {
    bool         uniform = false; ///< the uniform bar, else the seed bar
    unsigned int degree  = 10, cells = 10;
  };

  /// "7" (FE_Q(10) x 7) or "4x7" (FE_Q(4) x 7), after "uniform/" for the
  /// uniform bar.
  Mesh parse_mesh(std::string text)
  {
    Mesh              mesh;
    const std::string bar = "uniform/";
    if ((mesh.uniform = text.compare(0, bar.size(), bar) == 0))
      text = text.substr(bar.size());
    const auto x = text.find('x');
    if (x == std::string::npos)
      mesh.cells = std::stoi(text);
    else
      {
        mesh.degree = std::stoi(text.substr(0, x));
        mesh.cells  = std::stoi(text.substr(x + 1));
      }
    return mesh;
  }

  /// The uniform bar's tent at Omega (method.md), 0 for the seed bar.
  double exact_energy(const Mesh mesh, const double omega, const double gap)
  {
    const double period = 2 * M_PI / omega;
    return mesh.uniform ? gap * gap / (2 * (period - 3) * (period - 3)) : 0.0;
  }

  /// A list "2.13,2.15", or empty for a count.
  std::vector<double> parse_omegas(const std::string &text)
  {
    std::vector<double> list;
    if (text.find_first_of(".,") == std::string::npos)
      return list;
    std::size_t begin = 0;
    for (std::size_t end; (end = text.find(',', begin)) != std::string::npos; begin = end + 1)
      list.push_back(std::stod(text.substr(begin, end - begin)));
    list.push_back(std::stod(text.substr(begin)));
    return list;
  }

  nsm::Scene truncation_scene(const Mesh mesh, const unsigned int harmonics, const nsm::Integration rule,
                              const nsm::ContactMass mass)
  {
    nsm::Scene scene = testing_helpers::seed_scene(nsm::ForceSign::physical, 1.5, omega_end);
    if (mesh.uniform)
      {
        scene                             = testing_helpers::hb_scene("1", harmonics);
        scene.continuation.omega_max      = uniform_omega_end;
        scene.continuation.energy_max     = 1e-5;
      }
    scene.discretisation.degree       = mesh.degree;
    scene.discretisation.cells        = mesh.cells;
    scene.discretisation.contact_mass = mass;
    scene.receptance.method           = nsm::ReceptanceMethod::direct;
    scene.harmonic_balance.harmonics  = harmonics;
    scene.harmonic_balance.integration = rule;
    scene.output.stability_margin     = 1e-4;
    return scene;
  }

  double seconds_since(const std::chrono::steady_clock::time_point start)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
} // namespace

int main(int argc, char **argv)
{
  nsm::use_one_thread();
  const Mesh                mesh   = parse_mesh(argc > 1 ? argv[1] : "10");
  const std::vector<double> listed = parse_omegas(argc > 2 ? argv[2] : "10");
  const unsigned int        count  = listed.empty() ? (argc > 2 ? std::atoi(argv[2]) : 10) : listed.size();
  const nsm::Integration rule =
    argc > 3 && std::string(argv[3]) == "sampled" ? nsm::Integration::sampled : nsm::Integration::exact;
  const nsm::ContactMass mass =
    argc > 4 && std::string(argv[4]) == "consistent" ? nsm::ContactMass::consistent : nsm::ContactMass::redistributed;
  std::vector<unsigned int> ms;
  for (int a = 5; a < argc; ++a)
    ms.push_back(std::atoi(argv[a]));
  if (ms.empty())
    ms = {20, 40, 80, 160};

  std::vector<double>                 omegas;
  std::vector<std::vector<Row>>       rows(ms.size(), std::vector<Row>(count));
  std::vector<double>                 seconds(ms.size());
  std::vector<double>                 backbone_seconds(ms.size());
  std::vector<std::size_t>            backbone_points(ms.size());
  std::vector<std::optional<nsm::BackbonePoint>> last(count);
  double                              gap = 0;
  for (std::size_t k = 0; k < ms.size(); ++k)
    {
      testing_helpers::HbModel model(truncation_scene(mesh, ms[k], rule, mass));
      // The cost a user pays at this M: a whole backbone over the range.
      const auto          backbone_start = std::chrono::steady_clock::now();
      const nsm::Backbone backbone       = model.backbone();
      backbone_seconds[k]                = seconds_since(backbone_start);
      backbone_points[k]                 = backbone.points.size();
      const auto start = std::chrono::steady_clock::now();
      if (k == 0)
        {
          const double grazing = std::sqrt(model.receptance.poles().front());
          const double end     = model.scene.continuation.omega_max;
          for (unsigned int i = 0; i < count; ++i)
            {
              omegas.push_back(listed.empty() ? grazing + (end - grazing) * (i + 0.5) / count : listed[i]);
              try
                {
                  last[i] = nsm::solve_on_branch(model.hb, model.branch, backbone, omegas[i], true);
                }
              catch (const nsm::NumericalError &)
                {}
            }
        }
      else
        for (unsigned int i = 0; i < count; ++i)
          if (last[i])
            last[i] = testing_helpers::with_more_harmonics(model, *last[i]);
      seconds[k] = seconds_since(start);
      const nsm::ContactLaw law = model.hb.law();
      gap                       = model.scene.contact.gap;
      for (unsigned int i = 0; i < count; ++i)
        if (last[i])
          {
            Row &row   = rows[k][i];
            row.on_main = k > 0 || last[i]->branch == nsm::Branch::main;
            row.energy  = last[i]->measures.energy;
            const nsm::PeriodicField field(model.hb, model.discretisation, *last[i]);
            row.orbit = nsm::refine_point(field, model.discretisation, law, model.scene.output, {});
          }
      std::fprintf(stderr, "M = %u: %.2f s\n", ms[k], seconds[k]);
    }

  std::printf("omega,M,hb_found,hb_energy,orbit_found,orbit_energy,isolation,floquet_max,"
              "error_against_own_orbit,error_against_reference,exact_energy\n");
  for (unsigned int i = 0; i < count; ++i)
    {
      // The reference: the orbit shot from the largest M whose point converged.
      std::optional<double> reference;
      for (std::size_t k = ms.size(); k-- > 0 && !reference;)
        if (rows[k][i].orbit && rows[k][i].orbit->converged)
          reference = rows[k][i].orbit->energy;
      for (std::size_t k = 0; k < ms.size(); ++k)
        {
          const Row &row   = rows[k][i];
          const bool found = row.orbit && row.orbit->converged;
          std::printf("%.6f,%u,%d,%.10e,%d,%.10e,%.3e,%.6f,%.3e,%.3e,%.10e\n", omegas[i], ms[k], row.on_main, row.energy,
                      found, found ? row.orbit->energy : 0.0, found ? row.orbit->isolation : 0.0,
                      found ? row.orbit->floquet_max : 0.0, found ? row.energy / row.orbit->energy - 1 : NAN,
                      reference && row.energy > 0 ? row.energy / *reference - 1 : NAN,
                      exact_energy(mesh, omegas[i], gap));
        }
    }
  for (std::size_t k = 0; k < ms.size(); ++k)
    std::printf("# M = %u: a backbone to %.2f in %.2f s (%zu points); the points at the Omega %.3f s (%s)\n", ms[k],
                mesh.uniform ? uniform_omega_end : omega_end, backbone_seconds[k], backbone_points[k], seconds[k],
                k == 0 ? "solve_on_branch" : "one Newton solve per Omega from M / 2");
  return 0;
}
