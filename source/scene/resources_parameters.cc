#include <nsm/scene/resources_parameters.h>
#include <nsm/scene/scene_entries.h>

#include <deal.II/base/parameter_handler.h>

namespace nsm
{
  namespace
  {
    using namespace scene_entries;
  } // namespace

  void ResourcesParameters::declare(ParameterHandler &prm)
  {
    const ResourcesParameters d;
    prm.enter_subsection("Resources");
    prm.declare_entry("Memory limit",
                      text(d.memory_limit),
                      Patterns::Double(0, 1e9),
                      "MiB a run may use; 0 = the memory the machine has available (and the process's "
                      "address-space limit). A scene whose estimated need exceeds it is refused before "
                      "any work, naming the entries that drive the estimate; a limit below the process's own "
                      "share (about 200 MiB) fits no scene and is refused.");
    prm.leave_subsection();
  }

  void ResourcesParameters::parse(ParameterHandler &prm)
  {
    prm.enter_subsection("Resources");
    memory_limit = prm.get_double("Memory limit");
    prm.leave_subsection();
  }
} // namespace nsm
