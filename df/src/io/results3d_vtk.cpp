// ParaView frames of a 3D forward run: polyhedral blocks and contacts as VTK
// XML unstructured grids (common's VtuGrid), one pair per output frame; the
// .pvd that strings them together is common's write_pvd(). docs/formats.md.
#include <cstdint>
#include <string>
#include <vector>

#include "dda/common/vtu_writer.hpp"
#include "dda/df/io/results3d.hpp"

namespace dda::df3 {

void write_blocks3_frame_vtu(const std::string& path, const Simulation3& sim, const std::vector<Polyhedron>& initial) {
  VtuGrid g(sim.model().origin);
  std::vector<std::int64_t> id;
  std::vector<std::int32_t> fixed, material;
  std::vector<double> disp, vel, rot, stress, point_disp;
  const auto& blocks = sim.blocks();
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const Polyhedron& b = blocks[i];
    const Polyhedron& b0 = initial[i];
    for (std::size_t k = 0; k < b.vertices.size(); ++k) {
      g.add_point(b.vertices[k]);
      const Vec3 d = b.vertices[k] - b0.vertices[k];
      point_disp.insert(point_disp.end(), {d.x(), d.y(), d.z()});
    }
    std::vector<std::vector<int>> faces;
    for (const PolyFace& f : b.faces) faces.push_back(f.vertices);
    g.add_polyhedron(b.vertices.size(), faces);
    id.push_back(static_cast<std::int64_t>(i));
    fixed.push_back(sim.model().fixed[i] ? 1 : 0);
    // 0: materials.default, k + 1: materials.zones[k] (Model3::block_material).
    material.push_back(sim.model().block_material.empty() ? 0 : sim.model().block_material[i]);
    // Both centroids recomputed from the vertices, so a block at rest shows 0.
    const Vec3 dc = block_geometry(b.vertices, b.faces).centroid - block_geometry(b0.vertices, b0.faces).centroid;
    disp.insert(disp.end(), {dc.x(), dc.y(), dc.z()});
    const Vector12d& v = sim.velocities()[i];
    vel.insert(vel.end(), {v[0], v[1], v[2]});
    rot.insert(rot.end(), {v[3], v[4], v[5]});
    // ParaView reads six components as a symmetric tensor XX YY ZZ XY YZ XZ.
    const Vector6d& s = sim.stresses()[i];
    stress.insert(stress.end(), {s[0], s[1], s[2], s[5], s[3], s[4]});
  }
  g.point_data("displacement", 3, std::move(point_disp));
  g.cell_data("block_id", 1, std::move(id));
  g.cell_data("fixed", 1, std::move(fixed));
  g.cell_data("material", 1, std::move(material));
  g.cell_data("displacement", 3, std::move(disp));
  g.cell_data("velocity", 3, std::move(vel));
  g.cell_data("rotation_rate", 3, std::move(rot));
  g.cell_data("stress", 6, std::move(stress));
  g.write(path);
}

void write_contacts3_vtu(const std::string& path, const Simulation3& sim) {
  VtuGrid g(sim.model().origin);
  std::vector<std::int32_t> state, kind, bi, bj, joint;
  std::vector<double> normal, fn, fs;
  for (const Contact3& c : sim.contacts()) {
    g.add_point(c.point_now);
    g.add_cell(1, kVtkVertex);
    state.push_back(static_cast<std::int32_t>(c.state));
    kind.push_back(static_cast<std::int32_t>(c.kind));
    bi.push_back(c.i);
    bj.push_back(c.j);
    joint.push_back(c.joint);
    normal.insert(normal.end(), {c.geo.normal.x(), c.geo.normal.y(), c.geo.normal.z()});
    fn.push_back(c.normal_force);
    const Vec3 shear = c.shear_force.x() * c.geo.t1 + c.shear_force.y() * c.geo.t2;
    fs.insert(fs.end(), {shear.x(), shear.y(), shear.z()});
  }
  g.cell_data("state", 1, std::move(state));
  g.cell_data("kind", 1, std::move(kind));
  g.cell_data("normal", 3, std::move(normal));
  g.cell_data("normal_force", 1, std::move(fn));
  g.cell_data("shear_force", 3, std::move(fs));
  g.cell_data("block_i", 1, std::move(bi));
  g.cell_data("block_j", 1, std::move(bj));
  g.cell_data("joint", 1, std::move(joint));
  g.write(path);
}

void write_frame_vtu(const Simulation3& sim, const Results3& results, const std::string& blocks_path,
                     const std::string& contacts_path) {
  write_blocks3_frame_vtu(blocks_path, sim, results.blocks.blocks);
  if (!contacts_path.empty()) write_contacts3_vtu(contacts_path, sim);
}

}  // namespace dda::df3
