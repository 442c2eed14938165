#include <nsm/base/errors.h>
#include <nsm/base/text.h>
#include <nsm/verification/verification_checkpoint.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <ios>
#include <sstream>

namespace nsm
{
  namespace
  {
    constexpr const char *format_line = "nsm-bar verification checkpoint 1";

    /// The results a line holds, in order.
    std::vector<double *> fields(PointVerification &v)
    {
      return {&v.time.periodicity_defect, &v.time.periodicity_defect_end, &v.time.energy_drift, &v.time.impulse,
              &v.time.contact_fraction, &v.impulse_ratio};
    }

    [[noreturn]] void damaged(const std::string &path, const unsigned int line, const std::string &why)
    {
      throw InputError("command line: --resume: '" + printable(path) + "' is not a checkpoint nsm-bar wrote (line " +
                       std::to_string(line) + ": " + why + "): run the scene without --resume");
    }

    double number(const std::string &token, const std::string &path, const unsigned int line)
    {
      char *end = nullptr;
      errno     = 0;
      const double value = std::strtod(token.c_str(), &end);
      if (token.empty() || *end != '\0' || errno != 0 || !std::isfinite(value))
        damaged(path, line, "a finite number expected");
      return value;
    }
  } // namespace

  void write_verification_checkpoint(std::ostream &out, const Backbone &backbone,
                                     const std::vector<std::optional<PointVerification>> &verifications,
                                     const Scene::Output &output)
  {
    out << format_line << "\nsettings " << output.verify_steps << ' ' << output.verify_periods << '\n'
        << std::hexfloat;
    for (std::size_t i = 0; i < verifications.size(); ++i)
      if (verifications[i])
        {
          PointVerification v = *verifications[i];
          out << "point " << std::dec << i << ' ' << std::hexfloat << backbone.points[i].omega;
          for (const double *value : fields(v))
            out << ' ' << *value;
          out << '\n';
        }
    out << "end\n";
  }

  std::vector<std::optional<PointVerification>> read_verification_checkpoint(const std::string   &path,
                                                                             const Backbone      &backbone,
                                                                             const Scene::Output &output)
  {
    std::vector<std::optional<PointVerification>> known(backbone.points.size());
    std::ifstream                                 in(path);
    if (!in)
      return known;
    std::string  line;
    unsigned int number_read = 0;
    const auto   next        = [&]() -> std::istringstream {
      if (!std::getline(in, line))
        damaged(path, number_read, "it ends early");
      ++number_read;
      return std::istringstream(line);
    };
    if (next().str() != format_line)
      damaged(path, number_read, "'" + std::string(format_line) + "' expected");
    std::istringstream settings = next();
    std::string        key;
    unsigned int       steps = 0, periods = 0;
    if (!(settings >> key >> steps >> periods) || key != "settings")
      damaged(path, number_read, "'settings' expected");
    if (steps != output.verify_steps || periods != output.verify_periods)
      return known;
    for (std::istringstream row = next(); row.str() != "end"; row = next())
      {
        std::string index, omega;
        if (!(row >> key >> index >> omega) || key != "point")
          damaged(path, number_read, "'point' or 'end' expected");
        const double i = number(index, path, number_read);
        if (!(i >= 0 && i < known.size() && i == std::floor(i)) ||
            number(omega, path, number_read) != backbone.points[std::size_t(i)].omega)
          damaged(path, number_read, "a point of the resumed backbone expected");
        PointVerification v{};
        for (double *value : fields(v))
          {
            std::string token;
            row >> token;
            *value = number(token, path, number_read);
          }
        v.verified                 = v.time.periodicity_defect <= output.verify_tolerance;
        known[std::size_t(i)]      = v;
      }
    return known;
  }
} // namespace nsm
