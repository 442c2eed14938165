#include <nsm/base/checkpoint_reader.h>
#include <nsm/verification/point_checkpoint.h>
#include <nsm/verification/verification_checkpoint.h>

#include <limits>
#include <sstream>

namespace nsm
{
  namespace
  {
    constexpr const char *verification_format_line = "nsm-bar verification checkpoint 2";

    /// The results a line holds, in order (V: PointVerification, const or not).
    template <typename V>
    auto fields(V &v)
    {
      return std::vector{&v.time.periodicity_defect, &v.time.periodicity_defect_end, &v.time.energy_drift,
                         &v.time.impulse, &v.time.contact_fraction, &v.impulse_ratio, &v.time.energy_start};
    }
  } // namespace

  void write_verification_checkpoint(std::ostream &out, const Backbone &backbone,
                                     const std::vector<std::optional<PointVerification>> &verifications,
                                     const OutputParameters &output)
  {
    out << verification_format_line << "\nsettings " << output.verify_steps << ' ' << output.verify_periods << '\n';
    write_point_lines(out, backbone, verifications, [&](const PointVerification &v) {
      for (const double *value : fields(v))
        out << ' ' << exact(*value);
    });
  }

  std::vector<std::optional<PointVerification>> read_verification_checkpoint(const std::string   &path,
                                                                             const Backbone      &backbone,
                                                                             const OutputParameters &output)
  {
    std::vector<std::optional<PointVerification>> known(backbone.points.size());
    CheckpointReader                              reader(path);
    std::istringstream                            settings;
    if (!start_point_checkpoint(reader, verification_format_line, settings))
      return known;
    constexpr std::size_t any = std::numeric_limits<unsigned int>::max();
    const std::size_t     steps = reader.count(settings, any), periods = reader.count(settings, any);
    if (steps != output.verify_steps || periods != output.verify_periods)
      return known;
    read_point_lines(reader, backbone, [&](const std::size_t i, std::istringstream &row) {
      PointVerification v{};
      for (double *value : fields(v))
        *value = reader.number(row);
      v.verified = v.time.periodicity_defect <= output.verify_tolerance;
      known[i]   = v;
    });
    return known;
  }
} // namespace nsm
