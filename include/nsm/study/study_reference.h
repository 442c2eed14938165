// The fine backbone reference of a study (Study/Reference cells): the base
// scene on uniform meshes of one degree, coarse to fine, computed once and
// kept in the output directory as reference.csv. The finest level is the
// reference; the next coarser one shows how far it has converged.
#pragma once

#include <nsm/base/csv.h>
#include <nsm/study/study_row.h>

#include <string>
#include <vector>

namespace nsm
{
  /// Computes the main-branch points of `levels` (coarse to fine) at the
  /// study's Backbone omegas and writes directory/reference.csv, unless the
  /// file exists: run_study has checked that the directory holds this
  /// scene's study. Returns where the reference came from ("computed in ..."
  /// or "read from ...").
  std::string keep_fine_reference(const std::vector<StudyScene> &levels, const std::string &directory);

  /// The run summary's lines on reference.csv's `table`: its origin, where it
  /// found the main branch, and how much its finest level changed from the
  /// next coarser.
  std::vector<std::string> fine_reference_notes(const CsvTable &table, const std::vector<StudyScene> &levels,
                                                const std::string &origin);

  /// The finest level's points in reference.csv's `table`.
  FineReference read_fine_reference(const CsvTable &table, const std::vector<StudyScene> &levels);
} // namespace nsm
