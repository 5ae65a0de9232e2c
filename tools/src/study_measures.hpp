#pragma once
// The measures of a pipeline case (docs/studies.md), read from the files
// `dda run` wrote into the case's folder: stats.json for the blocks,
// results.h5 for the forward run. The kinds and their keys are read in
// tools/study/src/measure.cpp; here is what each one computes.
#include <filesystem>
#include <vector>

#include "dda/study/measure.hpp"

namespace dda::cli {

// One value per measure, in order. InputError naming the file and the
// measure when a file lacks what a measure needs (no forward run, no such
// point, no such statistic).
std::vector<double> pipeline_measures(const std::filesystem::path& case_dir,
                                      const std::vector<study::MeasureSpec>& measures);

}  // namespace dda::cli
