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

  std::size_t estimated_memory(const Scene &scene)
  {
    const auto  &d     = scene.discretisation;
    const auto  &o     = scene.output;
    const double cells = largest_cells(d), dofs = cells * d.degree + 1;
    // The mesh, K and M, and band copies of the pencil and its factors.
    double bytes = process_bytes + bytes_per_cell * cells + bytes_per_nonzero * dofs * (2 * d.degree + 1) +
                   8.0 * dofs * (3 * d.degree + 1) * 3;
    if (o.backbone || o.fields())
      {
        const double m = scene.harmonic_balance.harmonics + 1;
        const double n = scene.harmonic_balance.basis == HarmonicBasis::full ? 2 * m - 1 : m;
        const double samples = std::max<double>(scene.harmonic_balance.samples(), 8 * m);
        bytes += 8 * (6 * n * n + 4 * n * samples);
        // Each field keeps one nodal vector per basis function, and its
        // space-time samples.
        const double fields =
          o.fields_at.size() + (o.fields_every > 0 ? double(scene.continuation.max_steps) / o.fields_every : 0);
        bytes += fields * 8 * dofs * (n + 2.0 * scene.field_time_samples());
      }
    return static_cast<std::size_t>(std::min(bytes, 1e19));
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

  void check_memory(const std::size_t bytes, const ResourcesParameters &resources, const DiscretisationParameters &d)
  {
    const double need = bytes, have = available_memory(resources);
    if (need <= have)
      return;
    std::ostringstream s;
    s.precision(3);
    s << "the scene needs about " << need / (1 << 20) << " MiB of memory (an estimate from "
      << "Discretisation/Cells = " << d.cells << " and Discretisation/Degree = " << d.degree
      << ", Harmonic balance/Harmonics and the fields asked for), more than the "
      << have / (1 << 20) << " MiB "
      << (resources.memory_limit > 0 ? "of Resources/Memory limit" :
                                             "the machine has available (or the process's address-space limit allows)")
      << ": reduce Discretisation/Cells or Discretisation/Degree";
    throw InputError(s.str());
  }

  std::string memory_note(const std::size_t need, const ResourcesParameters &resources)
  {
    std::ostringstream s;
    s.precision(3);
    s << "memory: about " << need / double(1 << 20) << " MiB estimated at the peak, "
      << available_memory(resources) / double(1 << 20) << " MiB available";
    return s.str();
  }
} // namespace nsm
