#include <nsm/base/errors.h>

#include <deal.II/base/exceptions.h>

#include <sstream>

namespace nsm
{
  std::string one_line_message(const dealii::ExceptionBase &e)
  {
    std::ostringstream info;
    e.print_info(info);
    std::istringstream words(info.str());
    std::string        message, word;
    while (words >> word)
      message += (message.empty() ? "" : " ") + word;
    return message;
  }
} // namespace nsm
