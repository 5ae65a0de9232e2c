#pragma once
// Outputs never overwrite inputs.
//
// `dda dl s.yaml -o s.yaml` would replace the scenario with a lines file the
// moment the run succeeds, and the user's only copy is gone. Every command
// with an output and input files calls the guard first, before any work, so
// a mistyped output name costs nothing (docs/reliability.md).
#include <string>
#include <vector>

namespace dda {

// Throws InputError naming both paths when an output is one of the inputs:
// the same real path, or, when both exist, the same file (st_dev, st_ino),
// so a hard link or a symlink to an input is caught too. `output_folders`
// are folders a command fills with files of its own naming (`dda run -o
// DIR`'s vtk/): no input may lie inside one. Empty paths are skipped.
void refuse_overwriting_inputs(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs,
                               const std::vector<std::string>& output_folders = {});

}  // namespace dda
