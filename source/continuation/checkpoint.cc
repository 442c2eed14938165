#include <nsm/base/checkpoint_reader.h>
#include <nsm/base/errors.h>
#include <nsm/base/text.h>
#include <nsm/continuation/checkpoint.h>
#include <nsm/harmonic_balance/harmonic_balance.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>

namespace nsm
{
  namespace
  {
    constexpr const char *format_line = "nsm-bar continuation checkpoint 4";

    /// The interrupted run's entries must be the scene's: the first that
    /// differs is named with both values.
    /// The interrupted run's entries must be the scene's: every one that
    /// differs is named, with both values.
    void check_entries(CheckpointReader &reader, const std::vector<std::string> &entries)
    {
      std::istringstream       header = reader.next("entries ");
      const std::size_t        n      = reader.count(header, entries.size() + 1000);
      std::vector<std::string> differences;
      for (std::size_t i = 0; i < std::max(n, entries.size()); ++i)
        {
          const std::string had = i < n ? reader.text_line() : std::string("no such entry");
          const std::string has = i < entries.size() ? entries[i] : std::string("no such entry");
          if (had != has)
            differences.push_back("the scene has '" + printable(has) + "', the interrupted run had '" +
                                  printable(had) + "'");
        }
      if (differences.empty())
        return;
      std::string message = "command line: --resume: ";
      for (const std::string &d : differences)
        message += (&d == &differences.front() ? "" : "; ") + d;
      throw InputError(message + "; a resumed run must share every entry that shapes its model and its "
                                 "continuation (run without --resume)");
    }

    BackboneEnd end_named(CheckpointReader &reader, const std::string &name)
    {
      for (const BackboneEnd end : {BackboneEnd::range, BackboneEnd::max_steps, BackboneEnd::lost,
                                    BackboneEnd::energy_max, BackboneEnd::refused, BackboneEnd::interrupted})
        if (name == backbone_end_name(end))
          return end;
      reader.damaged("an end of the continuation expected");
    }

    /// The model's fingerprint goes on with point `p`: the bits of its
    /// numbers (segment, Omega, residual norm, Newton iterations, unknowns)
    /// and of the residual vector `hb`, set to its Omega, gives it.
    std::uint64_t hash_point(const HarmonicBalance &hb, const BackbonePoint &p, const std::uint64_t hash)
    {
      std::vector<double> residual;
      hb.evaluate(p.x, &residual, nullptr, nullptr);
      const double numbers[] = {static_cast<double>(p.segment), p.omega, p.residual,
                                static_cast<double>(p.newton_iterations)};
      const std::uint64_t with_numbers = fnv1a(p.x.data(), p.x.size() * sizeof(double),
                                               fnv1a(numbers, sizeof numbers, hash));
      return fnv1a(residual.data(), residual.size() * sizeof(double), with_numbers);
    }

    /// The fingerprint line's value: the points' hash (hash_point from the
    /// empty hash, in order) after the text of the checkpoint's lines before
    /// it, in hexadecimal.
    std::string fingerprint(const std::string &text, const std::uint64_t points)
    {
      std::ostringstream out;
      out << std::hex << fnv1a(&points, sizeof points, fnv1a(text.data(), text.size()));
      return out.str();
    }

    /// The "point" lines: each point's numbers, its measures computed again
    /// with `hb`; `points_hash` goes on with each (hash_point).
    std::vector<BackbonePoint> read_points(CheckpointReader &reader, HarmonicBalance &hb,
                                           const std::size_t max_points, std::uint64_t &points_hash)
    {
      std::istringstream         header = reader.next("points ");
      std::vector<BackbonePoint> points(reader.count(header, max_points));
      for (BackbonePoint &p : points)
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
          p.measures  = hb.measure(p.x);
          points_hash = hash_point(hb, p, points_hash);
        }
      if (points.empty())
        reader.damaged("at least one point expected");
      return points;
    }

    /// The "companions" lines: the other checkpoints' names and hashes.
    CheckpointCompanions read_companions(CheckpointReader &reader)
    {
      CheckpointCompanions companions;
      std::istringstream   header = reader.next("companions ");
      for (std::size_t i = 0, n = reader.count(header, 2); i < n; ++i)
        {
          std::istringstream line(reader.text_line());
          std::string        name;
          std::uint64_t      hash = 0;
          if (!(line >> name >> std::hex >> hash))
            reader.damaged("a companion checkpoint's name and hash expected");
          companions[name] = hash;
        }
      return companions;
    }
  } // namespace

  void write_checkpoint(std::ostream &file, const ContinuationCheckpoint &c,
                        const std::vector<std::string> &computation_entries, HarmonicBalance &hb,
                        const CheckpointCompanions &companions)
  {
    std::ostringstream out;
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
    out << "\ngaps " << c.gap_searches.size() << '\n';
    for (const GapSearch &g : c.gap_searches)
      out << exact(g.from) << ' ' << exact(g.to) << ' ' << g.starts << ' ' << g.other_family << ' '
          << g.other_harmonic << ' ' << g.tongue
          << ' ' << g.above_energy_max << ' ' << exact(g.most_contact) << ' '
          // No contact of the mode before a gap from the range's near end.
          << (std::isfinite(g.contact_before) ? exact(g.contact_before) : std::string("-")) << ' '
          << (g.landed ? exact(*g.landed) : std::string("-")) << '\n';
    out << "points " << c.points.size() << '\n';
    for (const BackbonePoint &p : c.points)
      {
        out << "point " << p.segment << ' ' << exact(p.omega) << ' ' << exact(p.residual) << ' '
            << p.newton_iterations << ' ' << p.x.size();
        for (const double v : p.x)
          out << ' ' << exact(v);
        out << '\n';
      }
    out << "companions " << companions.size() << '\n';
    for (const auto &[name, hash] : companions)
      out << name << ' ' << std::hex << hash << std::dec << '\n';
    std::uint64_t points_hash = fnv1a(nullptr, 0);
    for (const BackbonePoint &p : c.points)
      {
        hb.set_omega(p.omega);
        points_hash = hash_point(hb, p, points_hash);
      }
    file << out.str() << "model " << fingerprint(out.str(), points_hash) << "\nend\n";
  }

  namespace
  {
    /// The next field of `line`: a number, or '-' for none (`what` names it
    /// where it is missing).
    std::optional<double> number_or_none(CheckpointReader &reader, std::istringstream &line, const std::string &what)
    {
      std::string field;
      if (!(line >> field))
        reader.damaged(what + " or '-' expected");
      if (field == "-")
        return std::nullopt;
      std::istringstream value(field);
      return reader.number(value);
    }
  } // namespace

  ContinuationCheckpoint read_checkpoint(const std::string &path, const BranchParameters &params, HarmonicBalance &hb)
  {
    CheckpointReader reader(path);
    std::error_code  error;
    if (!reader.opened())
      throw InputError("command line: --resume needs the interrupted run's " + std::string(checkpoint_file) +
                       " in Output/Directory, and '" + printable(path) +
                       (std::filesystem::exists(path, error) ?
                          "' cannot be read" :
                          "' does not exist (a run leaves one only where a stop signal ended it before its end and it "
                          "had traced a backbone to go on from)") +
                       ": run the scene without --resume");
    reader.expect(format_line);
    check_entries(reader, params.computation_entries);
    ContinuationCheckpoint c;
    const std::size_t      max_points = params.continuation.max_steps + 1;
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
    std::istringstream gaps = reader.next("gaps ");
    c.gap_searches.resize(reader.count(gaps, max_points));
    for (GapSearch &g : c.gap_searches)
      {
        std::istringstream line(reader.text_line());
        g.from           = reader.number(line);
        g.to             = reader.number(line);
        g.starts         = reader.count(line, 1000 * max_points);
        g.other_family   = reader.count(line, 1000 * max_points);
        g.other_harmonic = reader.count(line, g.other_family);
        g.tongue         = reader.count(line, 1000 * max_points);
        g.above_energy_max = reader.count(line, 1000 * max_points);
        g.most_contact   = reader.number(line);
        // No contact of the mode before a gap from the range's near end.
        g.contact_before = number_or_none(reader, line, "a gap search's contact before it")
                             .value_or(-std::numeric_limits<double>::infinity());
        g.landed         = number_or_none(reader, line, "a gap search's landing");
      }
    std::uint64_t points_hash = fnv1a(nullptr, 0);
    c.points                  = read_points(reader, hb, max_points, points_hash);
    c.companions              = read_companions(reader);
    const std::string text    = reader.text_read();
    if (reader.next("model ").str() != fingerprint(text, points_hash))
      throw InputError("command line: --resume: the points of '" + printable(path) +
                       "' are not this scene's model's solutions bit for bit: its mesh or receptance differ from "
                       "the interrupted run's (an entry that shapes them changed), or the file was edited: run "
                       "the scene without --resume");
    if (reader.text_line() != "end" || !reader.finished())
      reader.damaged("'end' as the last line expected");
    return c;
  }
} // namespace nsm
