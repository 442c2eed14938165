#include <nsm/base/checkpoint_reader.h>
#include <nsm/verification/verification_checkpoint.h>

#include <limits>
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
  } // namespace

  void write_verification_checkpoint(std::ostream &out, const Backbone &backbone,
                                     const std::vector<std::optional<PointVerification>> &verifications,
                                     const Scene::Output &output)
  {
    out << format_line << "\nsettings " << output.verify_steps << ' ' << output.verify_periods << '\n';
    for (std::size_t i = 0; i < verifications.size(); ++i)
      if (verifications[i])
        {
          PointVerification v = *verifications[i];
          out << "point " << i << ' ' << exact(backbone.points[i].omega);
          for (const double *value : fields(v))
            out << ' ' << exact(*value);
          out << '\n';
        }
    out << "end\n";
  }

  std::vector<std::optional<PointVerification>> read_verification_checkpoint(const std::string   &path,
                                                                             const Backbone      &backbone,
                                                                             const Scene::Output &output)
  {
    std::vector<std::optional<PointVerification>> known(backbone.points.size());
    CheckpointReader                              reader(path);
    if (!reader.opened())
      return known;
    if (reader.text_line() != format_line)
      reader.damaged("'" + std::string(format_line) + "' expected");
    std::istringstream settings = reader.next("settings ");
    constexpr std::size_t any = std::numeric_limits<unsigned int>::max();
    const std::size_t     steps = reader.count(settings, any), periods = reader.count(settings, any);
    if (steps != output.verify_steps || periods != output.verify_periods)
      return known;
    for (std::string line = reader.text_line(); line != "end"; line = reader.text_line())
      {
        const std::string key = "point ";
        if (line.compare(0, key.size(), key) != 0)
          reader.damaged("'point' or 'end' expected");
        std::istringstream row(line.substr(key.size()));
        const std::size_t  i = reader.count(row, known.size());
        if (i == known.size() || reader.number(row) != backbone.points[i].omega)
          reader.damaged("a point of the resumed backbone expected");
        PointVerification v{};
        for (double *value : fields(v))
          *value = reader.number(row);
        v.verified = v.time.periodicity_defect <= output.verify_tolerance;
        known[i]   = v;
      }
    return known;
  }
} // namespace nsm
