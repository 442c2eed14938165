#include <nsm/base/assertions.h>

#include <cstddef>
#include <stdexcept>

namespace nsm
{
  bool is_logic_error(const std::exception &e)
  {
    return dynamic_cast<const std::logic_error *>(&e) || dynamic_cast<const ExcPrecondition *>(&e) ||
           dynamic_cast<const dealii::ExcDimensionMismatch *>(&e) ||
           dynamic_cast<const dealii::ExcIndexRangeType<int> *>(&e) ||
           dynamic_cast<const dealii::ExcIndexRangeType<unsigned int> *>(&e) ||
           dynamic_cast<const dealii::ExcIndexRangeType<std::size_t> *>(&e) ||
           dynamic_cast<const dealii::ExcLowerRange *>(&e) || dynamic_cast<const dealii::ExcInternalError *>(&e) ||
           dynamic_cast<const dealii::ExcNotImplemented *>(&e);
  }

  void throw_on_failed_asserts() { dealii::deal_II_exceptions::disable_abort_on_exception(); }
} // namespace nsm
