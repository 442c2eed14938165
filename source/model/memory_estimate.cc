#include <nsm/model/band_cells.h>
#include <nsm/model/memory_estimate.h>
#include <nsm/scene/scene.h>

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

namespace nsm
{
  namespace
  {
    /// Measured on this code (peak resident memory above the process's
    /// start, FE_Q(1) x 2e5 and 4e5 cells, FE_Q(20) x 1e4): about 330 bytes
    /// per cell and 33 per nonzero of K and M; rounded up.
    constexpr double bytes_per_cell    = 400;
    constexpr double bytes_per_nonzero = 40;
    /// The process itself, its libraries loaded (measured: 163 MiB).
    constexpr double process_bytes = 200.0 * (1 << 20);
    /// What each backbone point keeps (its unknowns, its measures, the M / 2
    /// estimate's point, the tables' rows), over the point and per unknown:
    /// peaks measured at 2,000 and 20,000 points (FE_Q(10) x 7, M = 40 and
    /// 80) grew by 2.0 and 2.6 KiB a point, 1.4 KiB and 15 bytes per unknown;
    /// doubled, for the vectors' growth by doubling.
    constexpr double bytes_per_point         = 4096;
    constexpr double bytes_per_point_unknown = 32;
    /// Each receptance frequency's row (measured: 166 bytes, from 3e5 and
    /// 1e6 frequencies), rounded up and doubled.
    constexpr double bytes_per_frequency = 384;

    /// A line "Name: value kB" of a /proc file, in bytes; 0 if absent.
    double proc_value(const std::string &file, const std::string &name)
    {
      std::ifstream in(file);
      for (std::string line; std::getline(in, line);)
        if (line.rfind(name + ":", 0) == 0)
          return std::stod(line.substr(name.size() + 1)) * 1024;
      return 0;
    }

    /// The most cells a mesh of the scene reaches: adaptive refinement
    /// splits at most Refine fraction of the cells in each step.
    double largest_cells(const DiscretisationParameters &d)
    {
      const double cells = d.cells;
      if (d.refinement != Refinement::adaptive)
        return cells;
      return cells * std::pow(1 + d.adaptive_fraction, d.adaptive_steps) + d.adaptive_steps;
    }
  } // namespace

  MemoryEstimate estimated_memory(const Scene &scene)
  {
    const auto  &d     = scene.discretisation;
    const auto  &o     = scene.output;
    const double cells = largest_cells(d), dofs = cells * d.degree + 1;
    MemoryEstimate estimate;
    const auto     add = [&](const double bytes, const char *drivers) {
      estimate.bytes += bytes;
      if (bytes > estimate.largest_part)
        {
          estimate.largest_part = bytes;
          estimate.drivers      = drivers;
        }
    };
    // The mesh, K and M, and band copies of the pencil and its factors; the
    // band check's judge the same for its cells halved and its degree
    // raised by one (verification/space_estimate.h), and the estimate's
    // check with 2 M another pencil of the mesh and a harmonic balance with
    // twice the harmonics (verification/doubled_harmonics.h).
    const auto model = [&](const double n, const double p) {
      const double unknowns = n * p + 1;
      return bytes_per_cell * n + bytes_per_nonzero * unknowns * (2 * p + 1) + 8.0 * unknowns * (3 * p + 1) * 3;
    };
    const bool judged = o.backbone && o.error_estimate;
    add((judged ? 2 : 1) * model(cells, d.degree) + (judged ? model(2 * cells, d.degree + judge_degree_step) : 0),
        "Discretisation/Cells and Discretisation/Degree");
    add(bytes_per_frequency * double(o.receptance_frequencies.size()), "Output/Receptance frequencies");
    if (o.backbone || o.fields())
      {
        // Unknowns with M harmonics, and the largest harmonic balance's
        // (the estimate's check has twice the harmonics).
        const auto unknowns = [&](const double harmonics) {
          return scene.harmonic_balance.basis == HarmonicBasis::full ? 2 * harmonics + 1 : harmonics + 1;
        };
        const double most_harmonics = (judged ? 2 : 1) * scene.harmonic_balance.harmonics;
        const double n              = unknowns(scene.harmonic_balance.harmonics);
        const double largest        = unknowns(most_harmonics);
        const double samples        = std::max<double>(scene.harmonic_balance.samples(), 8 * (most_harmonics + 1));
        add(8 * (6 * largest * largest + 4 * largest * samples), "Harmonic balance/Harmonics");
        add(double(scene.continuation.max_steps) * (bytes_per_point + bytes_per_point_unknown * n),
            "Continuation/Max steps");
        // Each field keeps one nodal vector per basis function, and its
        // space-time samples.
        const double fields =
          o.fields_at.size() + (o.fields_every > 0 ? double(scene.continuation.max_steps) / o.fields_every : 0);
        add(fields * 8 * dofs * (n + 2.0 * scene.field_time_samples()),
            "Output/Fields at, Output/Fields every and Output/Field time samples");
      }
    if (scene.forcing.enabled())
      {
        // The forced harmonic balance's dense matrices (full basis), and
        // every curve's points up to Max steps, each with its unknowns.
        const double n       = 2.0 * scene.harmonic_balance.harmonics + 1;
        const double samples = std::max<double>(scene.harmonic_balance.samples(), 8 * (n + 1));
        add(8 * (6 * n * n + 4 * n * samples), "Harmonic balance/Harmonics");
        add(double(scene.forcing.amplitudes.size() + scene.forcing.omegas.size()) *
              double(scene.continuation.max_steps) * (bytes_per_point + bytes_per_point_unknown * n),
            "Forcing/Amplitudes, Forcing/Omegas and Continuation/Max steps");
      }
    estimate.bytes = std::min(estimate.bytes + process_bytes, 1e19);
    return estimate;
  }

  std::size_t available_memory(const ResourcesParameters &resources)
  {
    double available = resources.memory_limit > 0 ? resources.memory_limit * (1 << 20) :
                                                    proc_value("/proc/meminfo", "MemAvailable");
    if (!(available > 0)) // a kernel without MemAvailable
      available = proc_value("/proc/meminfo", "MemTotal");
    if (!(available > 0))
      available = 1e19;
    rlimit limit{};
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
      available = std::min(available, double(limit.rlim_cur) - proc_value("/proc/self/status", "VmSize") +
                                        proc_value("/proc/self/status", "VmRSS"));
    return available > 0 ? static_cast<std::size_t>(available) : 0;
  }

  void check_memory(const MemoryEstimate &need, const ResourcesParameters &resources)
  {
    const double have = available_memory(resources);
    if (need.bytes <= have)
      return;
    std::ostringstream s;
    s.precision(3);
    // Below the process's own share no mesh or harmonics can fit.
    if (resources.memory_limit > 0 && have < process_bytes)
      {
        s << "parameter 'Resources/Memory limit' = " << resources.memory_limit
          << " is out of range: allowed at least " << std::ceil(process_bytes / (1 << 20))
          << " (MiB; the process itself, its libraries loaded, needs about that much before any scene), or 0 "
             "(the machine's available memory)";
        throw InputError(s.str());
      }
    s << "the scene needs about " << need.bytes / (1 << 20) << " MiB of memory (an estimate; "
      << need.largest_part / (1 << 20) << " MiB of it for " << need.drivers << "), more than the "
      << have / (1 << 20) << " MiB "
      << (resources.memory_limit > 0 ? "of Resources/Memory limit" :
                                             "the machine has available (or the process's address-space limit allows)")
      << ": reduce " << need.drivers;
    throw InputError(s.str());
  }

  std::string memory_note(const MemoryEstimate &need, const ResourcesParameters &resources)
  {
    std::ostringstream s;
    s.precision(3);
    s << "memory: about " << need.bytes / double(1 << 20) << " MiB estimated at the peak, "
      << available_memory(resources) / double(1 << 20) << " MiB available";
    return s.str();
  }
} // namespace nsm
