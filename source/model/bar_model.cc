#include <nsm/base/errors.h>
#include <nsm/base/text.h>
#include <nsm/model/bar_model.h>
#include <nsm/scene/parameter_limits.h>
#include <nsm/scene/scene_entries.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/point.h>

#include <cmath>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>

namespace nsm
{
  namespace
  {
    /// muparser takes more than an expression in x: an assignment ("x = 1"),
    /// a list whose last value it returns ("1.5 - x, 2") and deal.II's random
    /// functions. Each is refused with the reason.
    void check_expression(const std::string &expression)
    {
      const auto refuse = [&](const std::string &why) {
        throw InputError("parameter 'Bar/Cross section' = '" + printable(expression) +
                         "' is not allowed: " + why + "; allowed: one expression in x");
      };
      int depth = 0;
      for (std::size_t i = 0; i < expression.size(); ++i)
        {
          const char c = expression[i], before = i > 0 ? expression[i - 1] : ' ';
          const char after = i + 1 < expression.size() ? expression[i + 1] : ' ';
          depth += c == '(' ? 1 : c == ')' ? -1 : 0;
          if (c == ',' && depth == 0)
            refuse("a comma separates two expressions");
          if (c == '=' && std::string("<>!=").find(before) == std::string::npos && after != '=')
            refuse("'=' assigns a variable");
        }
      static const std::regex identifier("[A-Za-z_][A-Za-z_0-9]*");
      for (auto word = std::sregex_iterator(expression.begin(), expression.end(), identifier);
           word != std::sregex_iterator();
           ++word)
        if (word->str().rfind("rand", 0) == 0)
          refuse("'" + word->str() + "' is random: the bar would differ from run to run");
      // A number as the scene's entries take it: not subnormal, not beyond
      // the doubles (scene_entries::outside_normal_range).
      static const std::regex number(R"((^|[^A-Za-z_0-9.])((\d+\.?\d*|\.\d+)([eE][+-]?\d+)?))");
      for (auto match = std::sregex_iterator(expression.begin(), expression.end(), number);
           match != std::sregex_iterator();
           ++match)
        if (scene_entries::outside_normal_range((*match)[2].str()))
          refuse("the number " + (*match)[2].str() + " is not a normal double (a magnitude below 2.2e-308, "
                 "subnormal, or beyond 1.8e308): write 0 or a normal number");
    }

    /// A(x) is checked this densely on [0, L], besides at every quadrature
    /// point where the model evaluates it: a section negative on a short
    /// interval between a coarse mesh's quadrature points is still refused.
    constexpr unsigned int section_samples = 1u << 17;
  } // namespace

  BarModel::BarModel(const BarParameters &bar)
    : length_(bar.length)
    , young_modulus_(bar.young_modulus)
    , density_(bar.density)
    , expression_(bar.cross_section)
    , section_(std::make_unique<dealii::FunctionParser<1>>(1))
  {
    const std::map<std::string, double> constants = {{"pi", M_PI},
                                                     {"L", length_}};
    check_expression(expression_);
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
        const std::string why = expression_.find_first_not_of(" \t") == std::string::npos ?
                                  std::string("it is empty") :
                                  one_line_message(e);
        throw InputError("parameter 'Bar/Cross section' = '" + printable(expression_) +
                         "' is not a valid expression in x (" + why +
                         "); allowed: a muparser expression in x, positive on [0, L], such as 1.5 - x, "
                         "exp(-x) or x < 0.5 ? 2 : 1");
      }
    for (unsigned int i = 0; i <= section_samples; ++i)
      cross_section(length_ * i / section_samples);
  }

  BarModel::~BarModel() = default;

  double BarModel::cross_section(const double x) const
  {
    const double a = section_->value(dealii::Point<1>(x));
    if (!(a >= 1 / magnitude_limit && a <= magnitude_limit))
      {
        std::ostringstream msg;
        msg.precision(17);
        msg << "parameter 'Bar/Cross section' = '" << printable(expression_)
            << "' is out of range: allowed A(x) > 0, within [" << scene_entries::format_value(1 / magnitude_limit)
            << ", " << scene_entries::format_value(magnitude_limit) << "] on [0, L], but A("
            << scene_entries::format_value(x) << ") = " << scene_entries::format_value(a);
        throw InputError(msg.str());
      }
    return a;
  }

  double travel_time(const BarParameters &bar)
  {
    return bar.length * std::sqrt(bar.density / bar.young_modulus);
  }

  double accumulation_frequency(const BarParameters &bar, const unsigned int mode)
  {
    return (2.0 * mode - 1) * M_PI / (2 * travel_time(bar));
  }

  double BarModel::travel_time() const
  {
    return nsm::travel_time({length_, young_modulus_, density_, expression_});
  }

  double BarModel::accumulation_frequency(const unsigned int mode) const
  {
    return nsm::accumulation_frequency({length_, young_modulus_, density_, expression_}, mode);
  }
} // namespace nsm
