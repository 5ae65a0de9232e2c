// ParaView frames of a forward run: blocks and contacts as VTK XML
// unstructured grids (common's VtuGrid), one pair per output frame; the .pvd
// that strings them together is common's write_pvd(). See docs/formats.md.
#include <cstdint>
#include <string>
#include <vector>

#include "dda/common/vtu_writer.hpp"
#include "dda/df/2d/block_kinematics.hpp"
#include "dda/df/io/results.hpp"

namespace dda::df {

void write_blocks_frame_vtu(const std::string& path, const Simulation& sim) {
  const Model& model = sim.model();
  VtuGrid g(model.origin);
  std::vector<std::int64_t> id;
  std::vector<std::int32_t> material;
  std::vector<double> disp, vel, rot, stress, point_disp;
  for (std::size_t i = 0; i < sim.blocks().size(); ++i) {
    const BlockState& b = sim.blocks()[i];
    const Block& b0 = model.blocks[i];
    for (std::size_t k = 0; k < b.vertices.size(); ++k) {
      g.add_point(b.vertices[k]);
      const Vec2 d = b.vertices[k] - b0.vertices[k];
      point_disp.insert(point_disp.end(), {d.x(), d.y(), 0.0});
    }
    g.add_cell(b.vertices.size(), kVtkPolygon);
    id.push_back(static_cast<std::int64_t>(i));
    material.push_back(model.block_material[i]);
    const Vec2 dc = b.geometry.centroid - block_geometry(b0.vertices).centroid;
    disp.insert(disp.end(), {dc.x(), dc.y(), 0.0});
    vel.insert(vel.end(), {b.velocity_end[0], b.velocity_end[1], 0.0});
    rot.push_back(b.velocity_end[2]);
    stress.insert(stress.end(), {b.stress[0], b.stress[1], b.stress[2]});
  }
  g.point_data("displacement", 3, std::move(point_disp));
  g.cell_data("block_id", 1, std::move(id));
  g.cell_data("material", 1, std::move(material));
  g.cell_data("velocity", 3, std::move(vel));
  g.cell_data("displacement", 3, std::move(disp));
  g.cell_data("rotation_rate", 1, std::move(rot));
  g.cell_data("stress", 3, std::move(stress));
  g.write(path);
}

void write_contacts_vtu(const std::string& path, const Simulation& sim) {
  VtuGrid g(sim.model().origin);
  std::vector<std::int32_t> state, vblock, eblock, joint;
  std::vector<double> normal, fn, fs;
  for (const Contact& c : sim.contacts()) {
    g.add_point(sim.blocks()[c.vblock].vertices[c.vertex]);
    g.add_cell(1, kVtkVertex);
    state.push_back(static_cast<std::int32_t>(c.state));
    vblock.push_back(c.vblock);
    eblock.push_back(c.eblock);
    joint.push_back(c.joint);
    // Outward normal of the edge (blocks are counter-clockwise): the tangent turned clockwise.
    normal.insert(normal.end(), {c.geo.tangent.y(), -c.geo.tangent.x(), 0.0});
    fn.push_back(c.normal_force);
    fs.push_back(c.shear_force);
  }
  g.cell_data("state", 1, std::move(state));
  g.cell_data("normal", 3, std::move(normal));
  g.cell_data("normal_force", 1, std::move(fn));
  g.cell_data("shear_force", 1, std::move(fs));
  g.cell_data("vertex_block", 1, std::move(vblock));
  g.cell_data("edge_block", 1, std::move(eblock));
  g.cell_data("joint", 1, std::move(joint));
  g.write(path);
}

void write_frame_vtu(const Simulation& sim, const Results& /*results*/, const std::string& blocks_path,
                     const std::string& contacts_path) {
  write_blocks_frame_vtu(blocks_path, sim);
  if (!contacts_path.empty()) write_contacts_vtu(contacts_path, sim);
}

}  // namespace dda::df
