#include <nsm/base/threads.h>

#include <deal.II/base/multithread_info.h>

namespace nsm
{
  void use_one_thread() { dealii::MultithreadInfo::set_thread_limit(1); }
} // namespace nsm
