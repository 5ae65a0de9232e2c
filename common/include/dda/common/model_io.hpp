#pragma once
// HDF5 files of the pipeline: lines (DL -> DC) and blocks (DC -> DF).
//
// Both are self-describing: root attributes `format` ("dda-lines" or
// "dda-blocks"), `format_version`, `units` ("SI: m, m^2, m^4"),
// `program_version`, `scenario_path`, `scenario` (the whole text), `seed`,
// `created_utc`. The layout of every dataset is documented in docs/formats.md.
// Writes are atomic. A file that is missing, not HDF5, or not of the expected
// format is an InputError naming the file.
#include <string>

#include "dda/common/block_model.hpp"
#include "dda/common/line_model.hpp"

namespace dda {

void write_lines_h5(const std::string& path, const LineModel& model);
LineModel read_lines_h5(const std::string& path);

void write_blocks_h5(const std::string& path, const BlockModel& model);
BlockModel read_blocks_h5(const std::string& path);

// The `format` attribute of an HDF5 file written by this project, or "" if
// the file is not one of ours (used by `dda stats` and `dda plot` to accept
// either kind of file).
std::string h5_format_of(const std::string& path);

}  // namespace dda
