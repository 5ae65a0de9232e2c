// The ParaView series' file names and its .pvd (df_outputs.hpp).
#include "df_outputs.hpp"

#include <cstdio>

#include "dda/common/vtk.hpp"

namespace dda::cli {

std::string frame_name(const char* kind, std::size_t frame) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "df_%s_%05zu.vtu", kind, frame);
  return buf;
}

void write_pvd_series(const std::filesystem::path& dir, const std::vector<double>& times, bool contacts,
                      bool bolts) {
  std::vector<PvdEntry> entries;
  for (std::size_t f = 0; f < times.size(); ++f) {
    entries.push_back({frame_name("blocks", f), times[f], 0, "blocks"});
    if (contacts) entries.push_back({frame_name("contacts", f), times[f], 1, "contacts"});
    if (bolts) entries.push_back({frame_name("bolts", f), times[f], contacts ? 2 : 1, "bolts"});
  }
  write_pvd((dir / "df.pvd").string(), entries);
}

}  // namespace dda::cli
