// The bolts of a frame as VTK line cells (bolts_vtk.hpp).
#include "dda/df/io/bolts_vtk.hpp"

#include <cstdint>
#include <vector>

#include "dda/common/vtu_writer.hpp"
#include "dda/df/core/bolt_law.hpp"
#include "dda/df/2d/simulation.hpp"
#include "dda/df/3d/simulation3d.hpp"

namespace dda::df {
namespace {

// `origin`: the model's local origin, so that the bolts line up with the
// blocks in the user's coordinates (results_vtk.cpp does the same).
template <int dim, class Origin>
void write_bolt_lines(const std::string& path, const std::vector<BoltStateOf<dim>>& bolts, const Origin& origin) {
  VtuGrid g(origin);
  std::vector<std::int32_t> id, broken;
  std::vector<double> force, length;
  for (std::size_t k = 0; k < bolts.size(); ++k) {
    const BoltStateOf<dim>& b = bolts[k];
    g.add_point(b.anchor);
    g.add_point(b.head);
    g.add_cell(2, kVtkLine);
    id.push_back(static_cast<std::int32_t>(k));
    // The force the run records for this step (0 once broken, as /bolts/force).
    force.push_back(b.force);
    length.push_back((b.head - b.anchor).norm());
    broken.push_back(b.broken ? 1 : 0);
  }
  g.cell_data("axial_force", 1, std::move(force));
  g.cell_data("bolt_id", 1, std::move(id));
  g.cell_data("length", 1, std::move(length));
  g.cell_data("broken", 1, std::move(broken));
  g.write(path);
}

}  // namespace

void write_bolts_vtu(const std::string& path, const Simulation& sim) {
  write_bolt_lines<2>(path, sim.bolts(), sim.model().origin);
}

}  // namespace dda::df

namespace dda::df3 {

void write_bolts_vtu(const std::string& path, const Simulation3& sim) {
  df::write_bolt_lines<3>(path, sim.bolts(), sim.model().origin);
}

}  // namespace dda::df3
