// A study: the scene as a base, every combination of its swept parameters
// run as one row of study.csv, over the ranks of MPI_COMM_WORLD.
#pragma once

#include <nsm/pipeline.h>
#include <nsm/scene.h>

#include <string>
#include <vector>

namespace nsm
{
  /// One combination of the swept values: the scene a row runs.
  struct StudyCombination
  {
    std::vector<std::string> key; ///< the swept parameters' values, as in study.csv
    Scene                    scene;
  };

  /// Every combination of the study in `path` (its base is `base`), first
  /// sweep outermost, each a scene validated as any scene file is: a bad
  /// combination is an InputError before anything runs. A combination that
  /// differs from an earlier one only in values its run does not use (Time
  /// samples under exact integration, graded or adaptive parameters of
  /// another refinement) is left out.
  std::vector<StudyCombination> study_combinations(const std::string &path, const Scene &base);

  /// The scenes of the fine backbone reference's levels (Study/Reference
  /// cells, coarse to fine): the base scene on uniform meshes of Reference
  /// degree, with a row's outputs.
  std::vector<Scene> reference_levels(const std::string &path, const Scene &base);

  /// Runs the rows that Output/Directory/study.csv does not hold yet, the
  /// rows dealt out over the MPI ranks in rounds; after each round rank 0
  /// rewrites study.csv whole (rows in combination order) and prints the
  /// progress. study.scene records the base scene: a directory holding
  /// another scene's study is an InputError. Needs MPI initialised.
  RunReport run_study(const std::string &path, const Scene &base);
} // namespace nsm
