// refinement.resume: the orbits a stopped run found come back exactly, and a
// resumed refinement ends with the orbits of one that was never stopped.
#include <nsm/base/checkpoint_reader.h>
#include <nsm/base/errors.h>
#include <nsm/base/progress.h>
#include <nsm/verification/orbit_refinement.h>
#include <nsm/verification/refinement_checkpoint.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>

#include "hb_model.h"

namespace
{
  using Orbits = std::vector<std::optional<nsm::PeriodicOrbit>>;

  void expect_same(const std::optional<nsm::PeriodicOrbit> &a, const std::optional<nsm::PeriodicOrbit> &b,
                   const std::size_t i)
  {
    ASSERT_EQ(a.has_value(), b.has_value()) << "point " << i;
    if (!a)
      return;
    EXPECT_EQ(a->converged, b->converged) << "point " << i;
    EXPECT_EQ(a->energy, b->energy) << "point " << i;
    EXPECT_EQ(a->contact_fraction, b->contact_fraction) << "point " << i;
    EXPECT_EQ(a->floquet_max, b->floquet_max) << "point " << i;
    EXPECT_EQ(a->isolation, b->isolation) << "point " << i;
    EXPECT_EQ(a->stable, b->stable) << "point " << i;
    ASSERT_EQ(a->displacement.size(), b->displacement.size()) << "point " << i;
    for (unsigned int j = 0; j < a->displacement.size(); ++j)
      EXPECT_EQ(a->displacement[j], b->displacement[j]) << "point " << i << ", DoF " << j;
  }

  /// A checkpoint file as the run writes it: the text, then its checksum.
  std::string write_file(const std::string &path, const std::string &text)
  {
    return nsm::write_checksummed(path, [&](std::ostream &out) { out << text; });
  }
} // namespace

TEST(RefinementCheckpoint, AResumedRefinementEndsWithTheOrbitsOfAWholeOne)
{
  nsm::Scene scene          = testing_helpers::orbit_model_scene(2, 20);
  scene.output.refine_every = 10;
  testing_helpers::HbModel model(scene);
  const nsm::Backbone      backbone = model.backbone();
  nsm::Progress            quiet("refinement in time", 0);
  const Orbits whole = nsm::refine_backbone(model.hb, model.discretisation, backbone, scene.output, quiet);

  // A run stopped after the first half of the points it shoots.
  Orbits      stopped = whole;
  std::size_t shot = 0, found = 0;
  for (const auto &o : whole)
    shot += o.has_value();
  for (std::size_t i = 0, n = 0; i < stopped.size(); ++i)
    if (stopped[i] && ++n > shot / 2)
      stopped[i].reset();
    else if (stopped[i])
      found += stopped[i]->converged;
  ASSERT_GE(shot, 6u);
  ASSERT_GE(found, 1u) << "no orbit found before the stop: the displacement is not checked";

  std::ostringstream text;
  nsm::write_refinement_checkpoint(text, backbone, stopped, scene.output);
  const std::string path  = write_file("refinement_checkpoint_test.resume", text.str());
  const Orbits      known = nsm::read_refinement_checkpoint(path, backbone, scene.output, model.discretisation.n_dofs());
  for (std::size_t i = 0; i < known.size(); ++i)
    expect_same(known[i], stopped[i], i);

  const Orbits resumed = nsm::refine_backbone(model.hb, model.discretisation, backbone, scene.output, quiet, known);
  for (std::size_t i = 0; i < resumed.size(); ++i)
    expect_same(resumed[i], whole[i], i);

  // A kept orbit is taken as it is, not shot again: a marked one stays marked.
  Orbits marked = known;
  for (auto &o : marked)
    if (o)
      {
        o->energy = -1;
        break;
      }
  const Orbits again = nsm::refine_backbone(model.hb, model.discretisation, backbone, scene.output, quiet, marked);
  for (std::size_t i = 0; i < again.size(); ++i)
    if (marked[i] && marked[i]->energy == -1)
      {
        EXPECT_EQ(again[i]->energy, -1) << "point " << i << " was shot again";
      }

  // Another Refine every selects other points: nothing is kept.
  nsm::OutputParameters other = scene.output;
  other.refine_every       = 5;
  for (const auto &o : nsm::read_refinement_checkpoint(path, backbone, other, model.discretisation.n_dofs()))
    EXPECT_FALSE(o.has_value());

  // Stability margin is applied anew: with a margin of 10 every orbit found
  // is stable (their largest |multiplier| is below 11), with the run's none.
  other                  = scene.output;
  other.stability_margin = 10;
  std::size_t stable = 0, stable_before = 0;
  for (const auto &o : nsm::read_refinement_checkpoint(path, backbone, other, model.discretisation.n_dofs()))
    if (o)
      {
        EXPECT_EQ(o->stable, o->converged);
        stable += o->stable;
      }
  for (const auto &o : known)
    stable_before += o && o->stable;
  EXPECT_EQ(stable, found);
  EXPECT_LT(stable_before, found);

  // A checkpoint cut short (with its checksum, or cut after it was
  // written), one with a digit changed where nothing else checks it (the
  // last number of a point's line, a displacement), or one of another mesh,
  // is refused naming --resume.
  const std::string cut = text.str().substr(0, text.str().size() * 2 / 3);
  const auto        raw = [&](const std::string &content) { std::ofstream(path) << content; };
  for (const auto &damage : std::vector<std::function<void()>>{
         [&] { write_file(path, cut); },
         [&] { raw(cut); },
         [&] {
           write_file(path, text.str());
           std::ifstream      in(path);
           std::ostringstream whole;
           whole << in.rdbuf();
           std::string       file  = whole.str();
           const std::size_t line  = file.find("\npoint ") + 1;
           const std::size_t digit = file.rfind("0x1.", file.find('\n', line)) + 4;
           ASSERT_GT(digit, line + 4) << "no hexadecimal number on the first point's line";
           file[digit] = file[digit] == '1' ? '2' : '1';
           raw(file);
         }})
    {
      damage();
      try
        {
          nsm::read_refinement_checkpoint(path, backbone, scene.output, model.discretisation.n_dofs());
          ADD_FAILURE() << "a damaged checkpoint was read";
        }
      catch (const nsm::InputError &e)
        {
          EXPECT_NE(std::string(e.what()).find("--resume"), std::string::npos) << e.what();
        }
    }
  write_file(path, text.str());
  EXPECT_THROW(nsm::read_refinement_checkpoint(path, backbone, scene.output, model.discretisation.n_dofs() + 1),
               nsm::InputError);
  std::remove(path.c_str());
}
