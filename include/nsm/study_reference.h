// The fine backbone reference of a study (Study/Reference cells): the base
// scene on uniform meshes of one degree, coarse to fine, computed once and
// kept in the output directory as reference.csv. The finest level is the
// reference; the next coarser one shows how far it has converged.
#pragma once

#include <nsm/study_row.h>

#include <string>
#include <vector>

namespace nsm
{
  /// Computes the main-branch points of `levels` (coarse to fine) at the
  /// study's Backbone omegas and writes directory/reference.csv, unless the
  /// file exists: run_study has checked that the directory holds this
  /// scene's study. Returns the run summary's lines: where the reference
  /// came from, and how much its finest level changed from the next coarser.
  std::vector<std::string> make_fine_reference(const std::vector<Scene> &levels, const std::string &directory);

  /// The finest level's points, read from directory/reference.csv.
  FineReference read_fine_reference(const std::vector<Scene> &levels, const std::string &directory);
} // namespace nsm
