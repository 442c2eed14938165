#include <nsm/base/checkpoint_reader.h>
#include <nsm/base/errors.h>
#include <nsm/base/text.h>
#include <nsm/continuation/checkpoint.h>
#include <nsm/harmonic_balance/harmonic_balance.h>

#include <sstream>

namespace nsm
{
  namespace
  {
    constexpr const char *format_line = "nsm-bar continuation checkpoint 1";

    /// The interrupted run's entries must be the scene's: the first that
    /// differs is named with both values.
    void check_entries(CheckpointReader &reader, const std::vector<std::string> &entries)
    {
      std::istringstream header = reader.next("entries ");
      const std::size_t  n      = reader.count(header, entries.size() + 1000);
      for (std::size_t i = 0; i < n; ++i)
        {
          const std::string line = reader.text_line();
          if (i >= entries.size() || line != entries[i])
            throw InputError("command line: --resume: the scene has '" +
                             printable(i < entries.size() ? entries[i] : std::string("no more entries")) +
                             "', the interrupted run had '" + printable(line) +
                             "'; a resumed run must share every entry outside Output (run without --resume)");
        }
      if (n != entries.size())
        throw InputError("command line: --resume: the scene has '" + printable(entries[n]) +
                         "', which the interrupted run did not have (run without --resume)");
    }

    BackboneEnd end_named(CheckpointReader &reader, const std::string &name)
    {
      for (const BackboneEnd end : {BackboneEnd::range, BackboneEnd::max_steps, BackboneEnd::lost,
                                    BackboneEnd::energy_max, BackboneEnd::refused, BackboneEnd::interrupted})
        if (name == backbone_end_name(end))
          return end;
      reader.damaged("an end of the continuation expected");
    }
  } // namespace

  void write_checkpoint(std::ostream &out, const ContinuationCheckpoint &c,
                        const std::vector<std::string> &computation_entries)
  {
    out << format_line << "\nentries " << computation_entries.size() << '\n';
    for (const std::string &entry : computation_entries)
      out << entry << '\n';
    out << "state " << c.segment << ' ' << c.leaps << ' ' << exact(c.span) << ' '
        << (c.step ? exact(*c.step) : std::string("-")) << ' ' << c.complete << ' ' << backbone_end_name(c.end)
        << "\nevents " << c.events.size() << '\n';
    for (const std::string &event : c.events)
      out << event << '\n';
    out << "folds " << c.folds.size();
    for (const double omega : c.folds)
      out << ' ' << exact(omega);
    out << "\npoints " << c.points.size() << '\n';
    for (const BackbonePoint &p : c.points)
      {
        out << "point " << p.segment << ' ' << exact(p.omega) << ' ' << exact(p.residual) << ' '
            << p.newton_iterations << ' ' << p.x.size();
        for (const double v : p.x)
          out << ' ' << exact(v);
        out << '\n';
      }
    out << "end\n";
  }

  ContinuationCheckpoint read_checkpoint(const std::string &path, const Scene &scene, HarmonicBalance &hb)
  {
    CheckpointReader reader(path);
    if (!reader.opened())
      throw InputError("command line: --resume needs the interrupted run's " + std::string(checkpoint_file) +
                       " in Output/Directory, and '" + printable(path) +
                       "' cannot be read: run the scene without --resume");
    reader.expect(format_line);
    check_entries(reader, scene.computation_entries);
    ContinuationCheckpoint c;
    const std::size_t      max_points = scene.continuation.max_steps + 1;
    std::istringstream     state      = reader.next("state ");
    c.segment                         = reader.count(state, max_points);
    c.leaps                           = reader.count(state, max_points);
    c.span                            = reader.number(state);
    std::string step, end;
    state >> step >> c.complete >> end;
    if (!state)
      reader.damaged("the continuation's state expected");
    if (step != "-")
      {
        std::istringstream s(step);
        c.step = reader.number(s);
      }
    c.end = end_named(reader, end);
    std::istringstream events = reader.next("events ");
    c.events.resize(reader.count(events, 100 * max_points));
    for (std::string &event : c.events)
      event = reader.text_line();
    std::istringstream folds = reader.next("folds ");
    c.folds.resize(reader.count(folds, max_points));
    for (double &omega : c.folds)
      omega = reader.number(folds);
    std::istringstream points = reader.next("points ");
    c.points.resize(reader.count(points, max_points));
    for (BackbonePoint &p : c.points)
      {
        std::istringstream line = reader.next("point ");
        p.segment               = reader.count(line, max_points);
        p.omega                 = reader.number(line);
        p.residual              = reader.number(line);
        p.newton_iterations     = reader.count(line, 1u << 30);
        p.x.resize(reader.count(line, hb.n_unknowns()));
        if (p.x.size() != hb.n_unknowns())
          reader.damaged(std::to_string(hb.n_unknowns()) + " unknowns expected");
        for (double &v : p.x)
          v = reader.number(line);
        hb.set_omega(p.omega);
        p.measures = hb.measure(p.x);
      }
    if (reader.text_line() != "end" || c.points.empty())
      reader.damaged("'end' after at least one point expected");
    return c;
  }
} // namespace nsm
