#pragma once
// ParaView output: VTK XML unstructured grids (.vtu) and collections (.pvd).
#include <string>
#include <vector>

#include "dda/common/block_model.hpp"
#include "dda/common/line_model.hpp"

namespace dda {

// Lines as VTK_LINE cells with cell data: set, kind, layer.
void write_lines_vtu(const std::string& path, const LineModel& model);
// Blocks as VTK_POLYGON cells with cell data: block id, area, layer; and the
// domain/excavation outline is not included (it is in the lines file).
void write_blocks_vtu(const std::string& path, const BlockModel& model);

struct PvdEntry {
  std::string file;   // relative to the .pvd
  double time = 0;
  int part = 0;
  std::string name;   // optional dataset name
};
void write_pvd(const std::string& path, const std::vector<PvdEntry>& entries);

}  // namespace dda
