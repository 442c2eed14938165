#include <nsm/model/bar_model.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>

#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

namespace nsm
{
  BarModel::BarModel(const Scene::Bar &bar)
    : length_(bar.length)
    , young_modulus_(bar.young_modulus)
    , density_(bar.density)
    , expression_(bar.cross_section)
    , section_(std::make_unique<dealii::FunctionParser<1>>(1))
  {
    const std::map<std::string, double> constants = {{"pi", M_PI},
                                                     {"L", length_}};
    // deal.II prints muparser's diagnostic to std::cerr before throwing; the
    // message below says the same once.
    std::ostringstream silenced;
    std::streambuf    *cerr = std::cerr.rdbuf(silenced.rdbuf());
    try
      {
        section_->initialize("x", expression_, constants);
        // muparser reports some errors only on the first evaluation.
        section_->value(dealii::Point<1>(0.0));
        std::cerr.rdbuf(cerr);
      }
    catch (const dealii::ExceptionBase &e)
      {
        std::cerr.rdbuf(cerr);
        throw InputError("parameter 'Bar/Cross section' = '" + expression_ +
                         "' is not a valid expression in x: " + one_line_message(e));
      }
    constexpr unsigned int samples = 1000;
    for (unsigned int i = 0; i <= samples; ++i)
      cross_section(length_ * i / samples);
  }

  BarModel::~BarModel() = default;

  double BarModel::cross_section(const double x) const
  {
    const double a = section_->value(dealii::Point<1>(x));
    if (!(a >= 1 / Scene::magnitude_limit && a <= Scene::magnitude_limit))
      {
        std::ostringstream msg;
        msg.precision(17);
        msg << "parameter 'Bar/Cross section' = '" << expression_
            << "' is out of range: allowed A(x) > 0, within [" << 1 / Scene::magnitude_limit
            << ", " << Scene::magnitude_limit << "] on [0, L], but A(" << x << ") = " << a;
        throw InputError(msg.str());
      }
    return a;
  }
} // namespace nsm
