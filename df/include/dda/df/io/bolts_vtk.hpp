#pragma once
// ParaView frames of the rock bolts, 2D and 3D: one VTK_LINE cell per bolt
// from its anchor to its head, where both ends are now, with the bolt's
// number (the order of /bolts/name in the results file), its axial force,
// length and whether it has broken as cell data. One file per output
// frame, next to the blocks and contacts of the same frame (docs/formats.md).
#include <string>

namespace dda::df {
class Simulation;
void write_bolts_vtu(const std::string& path, const Simulation& sim);
}  // namespace dda::df

namespace dda::df3 {
class Simulation3;
void write_bolts_vtu(const std::string& path, const Simulation3& sim);
}  // namespace dda::df3
