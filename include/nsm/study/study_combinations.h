// The rows of a study: every combination of its swept parameters as a
// scene, the fine reference's levels, and the base scene's fingerprint.
#pragma once

#include <nsm/study/study_parameters.h>

#include <string>
#include <vector>

namespace nsm
{
  /// A swept parameter's value in a combination whose run does not use it.
  inline const std::string unused_value = "-";

  /// One combination of the swept values: the scene a row runs.
  struct StudyCombination
  {
    std::vector<std::string> key; ///< the swept parameters' values, as in study.csv
    StudyScene               scene;
  };

  /// Every combination of the study in `path` (its base is `base`), first
  /// sweep outermost, each a scene validated as any scene file is: a bad
  /// combination is an InputError before anything runs. A combination that
  /// differs from an earlier one only in values its run does not use (Time
  /// samples under exact integration, graded or adaptive parameters of
  /// another refinement) is left out.
  std::vector<StudyCombination> study_combinations(const std::string &path, const StudyScene &base);

  /// The scenes of the fine backbone reference's levels (Study/Reference
  /// cells, coarse to fine): the base scene on uniform meshes of Reference
  /// degree, with a row's outputs.
  std::vector<StudyScene> reference_levels(const std::string &path, const StudyScene &base);

  /// The base scene as text, without what a rerun may change: the swept
  /// lists, the repeats, where the output goes and how it is shown. A
  /// study's directory records it in study.scene.
  std::string study_fingerprint(const std::string &path, const StudyScene &base);
} // namespace nsm
