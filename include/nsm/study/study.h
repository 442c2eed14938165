// A study: the scene as a base, every combination of its swept parameters
// run as one row of study.csv, over the ranks of MPI_COMM_WORLD.
#pragma once

#include <nsm/output/run_report.h>
#include <nsm/study/study_combinations.h>

#include <string>
#include <vector>

namespace nsm
{
  /// Runs the rows that Output/Directory/study.csv does not hold yet, the
  /// rows dealt out over the MPI ranks in rounds; after each round rank 0
  /// rewrites study.csv whole (rows in combination order) and prints the
  /// progress. study.scene records the base scene: a directory holding
  /// another scene's study is an InputError. Needs MPI initialised.
  RunReport run_study(const std::string &path, const StudyScene &base);
} // namespace nsm
