// Contact bookkeeping of the 3D step: detection with state carried over, and
// the open / sliding / locked rule (the 2D rules of df/src/2d/contact.cpp with a
// 2-component shear).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <tuple>
#include <unordered_map>
#include <numbers>
#include <string>
#include <utility>

#include "dda/common/error.hpp"
#include "dda/df/3d/broad_phase3d.hpp"
#include "dda/df/core/block_system.hpp"
#include "dda/df/3d/simulation3d.hpp"
#include "3d/bonds3d.hpp"
#include "3d/simulation3d_assembly.hpp"

namespace dda::df3 {

namespace {

struct Box {
  Vec3 lo, hi;
};

Box bounds(const Polyhedron& p) {
  Box b{p.vertices.front(), p.vertices.front()};
  for (const auto& v : p.vertices) {
    b.lo = b.lo.cwiseMin(v);
    b.hi = b.hi.cwiseMax(v);
  }
  return b;
}

bool within(const Box& a, const Box& b, double reach) {
  for (int k = 0; k < 3; ++k)
    if (a.lo[k] > b.hi[k] + reach || b.lo[k] > a.hi[k] + reach) return false;
  return true;
}

bool same_key(const Contact3& a, const Contact3& b) {
  return a.i == b.i && a.j == b.j && a.kind == b.kind && std::equal(a.ids, a.ids + 4, b.ids);
}

Eigen::Matrix<double, 3, 2> tangents(const ContactGeometry3& g) {
  Eigen::Matrix<double, 3, 2> t;
  t << g.t1, g.t2;
  return t;
}

// The shear anchor of an unloaded spring: P projected into j's contact
// plane (no tangential offset).
Vec3 unloaded_anchor(const ContactGeometry3& g) { return g.point_i - (g.point_i - g.point_j).dot(g.normal) * g.normal; }

Contact3 from_candidate(const ContactCandidate3& cand, int a, int b) {
  Contact3 c;
  c.i = cand.a_is_i ? a : b;
  c.j = cand.a_is_i ? b : a;
  c.kind = cand.kind;
  if (cand.kind == ContactKind3::VertexFace) {
    c.ids[0] = cand.vertex;
    c.ids[1] = cand.face;
  } else {
    c.ids[0] = cand.edge_i[0];
    c.ids[1] = cand.edge_i[1];
    c.ids[2] = cand.edge_j[0];
    c.ids[3] = cand.edge_j[1];
  }
  c.geo = cand.geo;
  c.ref_j = unloaded_anchor(cand.geo);
  c.point_now = cand.geo.point_i;
  return c;
}

// c takes over the state of the previous contact o at (nearly) the same
// point, possibly of another kind or with i and j swapped. The shear spring
// keeps its stretch: the tangential offset of i's point from the anchor on
// j is the same vector (reversed when the roles swap, as the anchor then
// lies on the other block); the slip direction likewise.
void inherit(Contact3& c, const Contact3& o) {
  c.friction = o.friction;
  c.strength = o.strength;
  c.slip_velocity = o.slip_velocity;
  c.slip_axis = (c.i != o.i ? -1.0 : 1.0) * o.slip_axis;
  const bool swapped = c.i != o.i;
  const Vec3 offset = (swapped ? -1.0 : 1.0) * (o.point_now - o.ref_j);
  c.state = o.state;
  c.ref_j = c.geo.point_i - offset;
  const Vec3 dir = (swapped ? -1.0 : 1.0) * (tangents(o.geo) * o.slip_dir);
  const Eigen::Vector2d d2 = tangents(c.geo).transpose() * dir;
  if (d2.norm() > 1e-12) c.slip_dir = d2.normalized();
  c.normal_force = o.normal_force;
  c.shear_force = o.shear_force;
  c.bonded = o.bonded;
  c.bond_area = o.bond_area;
  c.glued = o.glued;
}

// The candidates of one pair that stand for one point: closer than `merge`
// to the group's first candidate.
struct PointGroup {
  std::vector<Contact3> candidates;
  std::vector<bool> preferred;  // the candidate search's own choice for its vertex (or an edge pair)
  std::vector<bool> on_cut;     // the candidate lies on an artificial cut (on_artificial_cut3)
  const Contact3* previous = nullptr;  // the previous contact at this point, if any
};

double distance_to(const PointGroup& g, const Vec3& x) {
  double d = std::numeric_limits<double>::infinity();
  for (const Contact3& c : g.candidates) d = std::min(d, (c.geo.point_i - x).norm());
  return d;
}

// The candidate that stands for the group. A group that continues a contact
// keeps its contact plane: the candidate whose normal (seen from the old
// contact's block i) is closest to the old normal, e.g. the face a corner
// already rested on although it now projects onto a neighbouring face whose
// plane it has crossed less (the search's separating-axis choice, right for
// a vertex arriving, wrong for one sliding along an edge of its face). Ties:
// the same features as before, then the search's choice, then vertex-face.
// A new group takes the search's choice, vertex-face first. Before all
// that, a candidate on an artificial cut: where two parts of one body meet
// corner to corner, a corner lies on the faces beside the cut as well
// (gap 0 to each), and a contact on a side face would miss the glue.
const Contact3& representative(const PointGroup& g) {
  auto score = [&](size_t k) {
    const Contact3& c = g.candidates[k];
    double align = 0;
    int same = 0;
    if (g.previous) {
      const Contact3& o = *g.previous;
      align = c.geo.normal.dot(o.geo.normal) * (c.i == o.i ? 1.0 : -1.0);
      same = same_key(c, o) ? 1 : 0;
    }
    return std::make_tuple(g.on_cut[k] ? 1 : 0, std::round(align * 1e9), same, g.preferred[k] ? 1 : 0,
                           c.kind == ContactKind3::VertexFace ? 1 : 0);
  };
  size_t best = 0;
  for (size_t k = 1; k < g.candidates.size(); ++k)
    if (score(k) > score(best)) best = k;
  return g.candidates[best];
}

// One contact per point of the pair (a, b), each with the state of the
// previous contact at that point (nearest first, each passed on once).
// `cut_pair`: a and b are parts of one body and one has an artificial face.
std::vector<Contact3> contacts_of_pair(const std::vector<Polyhedron>& blocks,
                                       const std::vector<std::vector<PolyEdge>>& edges, int a, int b,
                                       ContactOptions3 opt, double merge,
                                       const std::vector<const Contact3*>& previous_of_pair, bool cut_pair) {
  opt.alternative_faces = true;
  std::vector<PointGroup> groups;
  for (const auto& cand : find_contacts3(blocks[a], edges[a], blocks[b], edges[b], opt)) {
    const Contact3 c = from_candidate(cand, a, b);
    PointGroup* home = nullptr;
    for (PointGroup& g : groups)
      if ((g.candidates.front().geo.point_i - c.geo.point_i).norm() <= merge) {
        home = &g;
        break;
      }
    if (!home) home = &groups.emplace_back();
    home->candidates.push_back(c);
    home->preferred.push_back(cand.preferred);
    home->on_cut.push_back(cut_pair && on_artificial_cut3(blocks, c));
  }
  // Closed contacts are matched first: where a group could continue
  // several previous contacts (an open corner in front of a free face
  // within `merge` of the edge crossing that bears the load), the one that
  // carries force keeps its state and plane; losing it dropped the last
  // support of a wedge's corner and let the wedge roll on its line of
  // intersection. An open contact has no spring state to lose.
  struct Match {
    int open;  // 1: the previous contact is open
    double distance;
    size_t group, old;
  };
  std::vector<Match> matches;
  for (size_t g = 0; g < groups.size(); ++g)
    for (size_t o = 0; o < previous_of_pair.size(); ++o) {
      const double dist = distance_to(groups[g], previous_of_pair[o]->point_now);
      if (dist <= merge)
        matches.push_back({previous_of_pair[o]->state == ContactState3::Open ? 1 : 0, dist, g, o});
    }
  std::sort(matches.begin(), matches.end(), [](const Match& x, const Match& y) {
    return std::tie(x.open, x.distance, x.group, x.old) < std::tie(y.open, y.distance, y.group, y.old);
  });
  std::vector<bool> old_done(previous_of_pair.size(), false);
  for (const Match& m : matches) {
    if (groups[m.group].previous || old_done[m.old]) continue;
    old_done[m.old] = true;
    groups[m.group].previous = previous_of_pair[m.old];
  }
  std::vector<Contact3> out;
  for (const PointGroup& g : groups) {
    Contact3 c = representative(g);
    if (g.previous) inherit(c, *g.previous);
    out.push_back(c);
  }
  return out;
}

}  // namespace

std::vector<Contact3> detect_contacts3(const std::vector<Polyhedron>& blocks, const std::vector<Contact3>& previous,
                                       double reach, double merge) {
  std::vector<Contact3> out;
  detect_contacts3(blocks, previous, reach, merge, out);
  return out;
}

void detect_contacts3(const std::vector<Polyhedron>& blocks, const std::vector<Contact3>& previous, double reach,
                      double merge, std::vector<Contact3>& out) {
  if (&out == &previous) throw InternalError("detect_contacts3: the output list is the previous one");
  ContactOptions3 opt;
  opt.reach = reach;
  // Slack of "the vertex projects onto the face" and "the crossing is inside
  // both edges", and of the edge-edge normal cone. Contacts at corners and
  // coplanar edges sit exactly on these boundaries and round-off or a
  // micrometre of motion moves them across; with 1e-9 slack a corner resting
  // on a face corner dropped in and out of the search from step to step.
  // Half the merge distance: a vertex that slid off its face by less than
  // that still bears on the face plane, and the edge crossing that takes
  // over is within `merge` of it (so inherits the contact).
  opt.tolerance = 0.5 * merge;
  opt.cone_tol = 1e-4;
  // Previous contacts by unordered block pair.
  std::unordered_map<std::uint64_t, std::vector<const Contact3*>> by_pair;
  auto key = [](int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) | static_cast<std::uint32_t>(std::max(a, b));
  };
  for (const Contact3& o : previous) by_pair[key(o.i, o.j)].push_back(&o);
  const std::vector<const Contact3*> none;

  std::vector<Box> box;
  for (const auto& b : blocks) box.push_back(bounds(b));
  const int n = static_cast<int>(blocks.size());
  // Candidate partners b > a of each block a from the grid, boxes grown by
  // reach on every side: a superset of the pairs `within` accepts (it still
  // decides), found in time linear in the number of blocks.
  std::vector<Box3> grid_boxes;
  for (const Box& bx : box) grid_boxes.push_back({bx.lo, bx.hi});
  const std::vector<std::pair<int, int>> pairs = broad_phase3(grid_boxes, reach);
  std::vector<std::size_t> first_pair(static_cast<std::size_t>(n) + 1, 0);  // pairs of a: first_pair[a] .. [a + 1]
  for (const auto& pair : pairs) ++first_pair[static_cast<std::size_t>(pair.first) + 1];
  for (int a = 0; a < n; ++a) first_pair[a + 1] += first_pair[a];
  // Each block's contacts go to a list of its own, joined in block order
  // below: pairs stay in (a, b) order, so the result is the same with any
  // number of threads.
  std::vector<std::vector<PolyEdge>> edges(static_cast<std::size_t>(n));
  // Small models on one thread: waking a second one costs more than their
  // whole search, and on a busy machine far more (docs/solver2d.md,
  // "Threads for small models").
  const bool threads = n > df::parallel_grain();
  std::vector<std::uint8_t> cut(static_cast<std::size_t>(n), 0);  // the block has a face on an artificial cut
#pragma omp parallel for schedule(static) if (threads)
  for (int a = 0; a < n; ++a) {
    edges[a] = polyhedron_edges(blocks[a]);
    cut[a] = std::any_of(blocks[a].faces.begin(), blocks[a].faces.end(),
                         [](const PolyFace& f) { return f.set == kArtificialSet; });
  }
  std::vector<std::vector<Contact3>> found(static_cast<std::size_t>(n));
#pragma omp parallel for schedule(dynamic, 8) if (threads)
  for (int a = 0; a < n; ++a) {
    std::vector<Contact3>& of_a = found[a];
    for (std::size_t p = first_pair[a]; p < first_pair[a + 1]; ++p) {
      const int b = pairs[p].second;
      if (!within(box[a], box[b], reach)) continue;
      const auto it = by_pair.find(key(a, b));
      const auto& old = it == by_pair.end() ? none : it->second;
      const bool cut_pair = (cut[a] || cut[b]) && blocks[a].body == blocks[b].body;
      std::vector<Contact3> pair = contacts_of_pair(blocks, edges, a, b, opt, merge, old, cut_pair);
      for (Contact3& c : pair) {
        if (c.state == ContactState3::Open) c.normal_force = 0;
        of_a.push_back(std::move(c));
      }
    }
  }
  // Joined in block order, in parallel into out's existing elements (only
  // the count's change is constructed or destroyed).
  std::vector<std::size_t> first(static_cast<std::size_t>(n) + 1, 0);
  for (int a = 0; a < n; ++a) first[a + 1] = first[a] + found[a].size();
  out.resize(first[n]);
#pragma omp parallel for schedule(static) if (threads)
  for (int a = 0; a < n; ++a) std::copy(found[a].begin(), found[a].end(), out.begin() + first[a]);
}

void add_contact_springs(const Contact3& c, ContactState3 state, double sign, const ContactSprings3& springs,
                         Assembly3& sys) {
  if (state == ContactState3::Open) return;
  const ContactGeometry3& g = c.geo;
  // Normal spring: K += k [en; gn][en; gn]^T, k the law's tangent over the
  // step (pn for the linear penalty).
  sys.add_spring_k<1>(c.i, c.j, sign * springs.normal_spring(g.dn0).k, g.en.transpose(), g.gn.transpose());
  if (state == ContactState3::Locked) sys.add_spring_k<2>(c.i, c.j, sign * springs.ps, g.es, g.gs);
}

void add_contact_loads(const Contact3& c, const ContactSprings3& springs, const std::vector<Vector12d>& known,
                       Assembly3& sys) {
  if (c.state == ContactState3::Open) return;
  const ContactGeometry3& g = c.geo;
  // A fixed block's known increment is part of the spring's initial stretch.
  const bool fi = sys.dof[c.i] < 0, fj = sys.dof[c.j] < 0;
  const df::NormalSpring normal = springs.normal_spring(g.dn0);
  double s0n = normal.s0;  // dn0 for the linear penalty
  if (fi) s0n += g.en.dot(known[c.i]);
  if (fj) s0n += g.gn.dot(known[c.j]);
  // Normal spring: F -= k s0 [en; gn].
  sys.add_spring_f<1>(c.i, c.j, normal.k, Eigen::Matrix<double, 1, 1>(s0n), g.en.transpose(), g.gn.transpose());
  if (c.state == ContactState3::Locked) {
    Eigen::Vector2d s0 = shear_offset(c);
    if (fi) s0 += g.es * known[c.i];
    if (fj) s0 += g.gs * known[c.j];
    sys.add_spring_f<2>(c.i, c.j, springs.ps, s0, g.es, g.gs);
    return;
  }
  // Sliding: the strength of the last iterate against the slip, on P of
  // block i and the reverse on Q of block j (es = [t1 t2]^T T_i(P),
  // gs = -[t1 t2]^T T_j(Q)).
  sys.add_f(c.i, -c.strength * g.es.transpose() * c.slip_dir);
  sys.add_f(c.j, -c.strength * g.gs.transpose() * c.slip_dir);
}

std::vector<ContactSprings3> contact_springs3(const Model3& m) {
  std::vector<ContactSprings3> out;
  auto add = [&](const df::JointProperties& joint, const std::string& which) {
    for (const auto& [key, value] : {std::pair{"normal_penalty", joint.normal_penalty},
                                     std::pair{"shear_penalty", joint.shear_penalty}})
      if (value && !(std::isfinite(*value) && *value > 0))
        throw InputError("The 3D " + which + "'s " + key + " must be a positive number (N/m).");
    ContactSprings3 s;
    s.pn = joint.normal_penalty.value_or(m.normal_penalty);
    // The run's ratio for a joint with a normal penalty of its own (2D's
    // shear_ratio); the run's ps, to the bit, for one without.
    s.ps = joint.shear_penalty ? *joint.shear_penalty
           : joint.normal_penalty ? m.shear_penalty / m.normal_penalty * s.pn
                                  : m.shear_penalty;
    s.normal = df::make_normal_law(joint, s.pn);  // InputError for an unknown law or a bad number
    out.push_back(std::move(s));
  };
  for (std::size_t k = 0; k < m.joint_sets.size(); ++k) add(m.joint_sets[k], "joint set " + std::to_string(k));
  add(m.default_joint, "default joint");
  return out;
}

ContactSprings3 glue_springs3(const ContactSprings3& default_joint) {
  ContactSprings3 glue = default_joint;
  glue.normal = std::make_shared<const df::PenaltyNormal>(glue.pn);
  return glue;
}

Eigen::Vector2d shear_offset(const Contact3& c) { return tangents(c.geo).transpose() * (c.geo.point_i - c.ref_j); }

df::FrictionInput friction_input3(const Contact3& c, double dt) {
  df::FrictionInput in;
  in.normal_force = c.normal_force;
  in.slip_velocity = c.slip_velocity;
  in.dt = dt;
  in.contact_length = c.bond_area;  // in 3D an area: the law's cohesion c bond_area is a force
  in.bonded = c.bonded;
  return in;
}

int slip_sign3(const Contact3& c) {
  if (c.state != ContactState3::Sliding) return 0;
  return (tangents(c.geo) * c.slip_dir).dot(c.slip_axis) >= 0 ? 1 : -1;
}

ContactState3 update_contact3(Contact3& c, const Model3& m, const ContactSprings3& springs,
                              const df::FrictionLaw& law, double dt, const Vector12d& di, const Vector12d& dj,
                              bool hold, bool& settled) {
  const ContactGeometry3& g = c.geo;
  const double eps = m.tolerance, pn = springs.pn, ps = springs.ps;
  const double dn = g.dn0 + g.en.dot(di) + g.gn.dot(dj);  // the gap (penetration negative): decides closing
  // The normal spring's force, as assembled; for the linear penalty
  // (s0 = dn0) the very numbers of -pn dn.
  const df::NormalSpring normal = springs.normal_spring(g.dn0);
  const double n = -normal.k * (normal.s0 + g.en.dot(di) + g.gn.dot(dj));
  const ContactState3 old = c.state;
  const double friction_used = old == ContactState3::Sliding ? c.strength : 0.0;  // what was assembled

  // Closing or sticking: the shear spring's anchor. A fresh contact starts
  // unloaded at the foot Q; a sliding contact that sticks keeps the friction
  // force it carried (spring stretched by F / ps along the slip, as in 2D).
  auto lock = [&]() {
    c.ref_j = unloaded_anchor(g);
    if (old == ContactState3::Sliding) c.ref_j -= tangents(g) * c.slip_dir * (friction_used / ps);
    return ContactState3::Locked;
  };
  c.shear_force.setZero();
  c.slip.setZero();
  c.slip_velocity = 0;

  if (c.glued) {  // one piece of rock: never opens, never slides, both springs stay on (placed locked)
    c.normal_force = n;
    c.shear_force = -ps * (shear_offset(c) + g.es * di + g.gs * dj);
    return ContactState3::Locked;
  }

  if (old == ContactState3::Open) {
    if (dn < -eps) {
      c.normal_force = n;
      return lock();
    }
    c.normal_force = 0;
    return ContactState3::Open;
  }

  // Tension beyond the band (and the bond's strength): the contact opens.
  if (n < -(bond_tension3(c, m) + pn * eps) && !hold) {
    // A bonded contact is locked (sliding broke the bond): its shear spring goes too.
    if (c.bonded) break_bond_in_tension3(c, m, springs, -ps * (shear_offset(c) + g.es * di + g.gs * dj));
    c.normal_force = 0;
    return ContactState3::Open;
  }
  c.normal_force = n;
  // Slip of P relative to the point of j under it in this iterate.
  const Eigen::Vector2d slip = g.es * di + g.gs * dj;
  c.slip_velocity = slip.norm() / dt;
  c.strength = law.strength(friction_input3(c, dt), c.friction);

  if (old == ContactState3::Locked) {
    const Eigen::Vector2d ds = shear_offset(c) + g.es * di + g.gs * dj;
    const Eigen::Vector2d fs = -ps * ds;
    if (fs.norm() > c.strength + ps * eps) {
      if (c.bonded) {  // the bond goes; friction alone holds from here on
        const double bonded_strength = c.strength;
        c.bonded = false;
        c.strength = law.strength(friction_input3(c, dt), c.friction);
        c.bond_released = (bonded_strength * bonded_strength - c.strength * c.strength) / (2 * ps);
      }
      c.slip_dir = ds.normalized();
      if (c.slip_axis.squaredNorm() == 0) c.slip_axis = tangents(g) * c.slip_dir;
      c.shear_force = -c.strength * c.slip_dir;
      return ContactState3::Sliding;
    }
    c.shear_force = fs;
    return ContactState3::Locked;
  }

  c.slip = slip;
  if (slip.dot(c.slip_dir) < -eps && !hold) return lock();
  // The friction direction stays fixed within the step: when the block is
  // nearly stuck the iterate's slip is a tiny residual whose direction
  // swings from one iterate to the next (following it diverged in a test).
  // finish_step turns it after the step, as the shear spring's return onto
  // the friction limit would. The strength is iterated to
  // agree with the normal force and slip speed it produces (as in 2D).
  const double floor = 1e-10 * pn;  // the force of a 1e-10 m penetration
  if (std::abs(c.strength - friction_used) > 1e-3 * c.strength + floor) settled = false;
  c.shear_force = -c.strength * c.slip_dir;
  return ContactState3::Sliding;
}

namespace {

// The faces of p through vertex u and (unless w < 0) vertex w.
std::vector<int> faces_at(const Polyhedron& p, int u, int w) {
  std::vector<int> out;
  for (int f = 0; f < static_cast<int>(p.faces.size()); ++f) {
    const auto& v = p.faces[f].vertices;
    if (std::find(v.begin(), v.end(), u) != v.end() && (w < 0 || std::find(v.begin(), v.end(), w) != v.end()))
      out.push_back(f);
  }
  return out;
}

}  // namespace

bool on_artificial_cut3(const std::vector<Polyhedron>& blocks, const Contact3& c) {
  const Polyhedron& i = blocks[c.i];
  const Polyhedron& j = blocks[c.j];
  if (i.body != j.body) return false;
  const double cos_tol = std::cos(10.0 * std::numbers::pi / 180.0);
  // An artificial face of p among `faces` whose outward normal is `side`
  // times the contact normal n (which points from j to i): +1 for block j,
  // -1 for block i.
  auto artificial_in_plane = [&](const Polyhedron& p, const std::vector<int>& faces, double side) {
    for (const int f : faces)
      if (p.faces[f].set == kArtificialSet && side * p.faces[f].normal.dot(c.geo.normal) >= cos_tol) return true;
    return false;
  };
  const bool vf = c.kind == ContactKind3::VertexFace;
  const std::vector<int> of_j = vf ? std::vector<int>{c.ids[1]} : faces_at(j, c.ids[2], c.ids[3]);
  const std::vector<int> of_i = vf ? faces_at(i, c.ids[0], -1) : faces_at(i, c.ids[0], c.ids[1]);
  return artificial_in_plane(j, of_j, 1.0) || artificial_in_plane(i, of_i, -1.0);
}

// The joint set of the contact's faces: the face of j under a vertex; for
// an edge pair, a face at j's edge whose plane is the contact's (else one at
// i's edge), the first with a set >= 0.
int contact_joint_set(const std::vector<Polyhedron>& blocks, const Contact3& c) {
  const Polyhedron& j = blocks[c.j];
  if (c.kind == ContactKind3::VertexFace) return j.faces[c.ids[1]].set;
  int best = -1;
  double best_align = -1;
  const Polyhedron& i = blocks[c.i];
  for (int f : faces_at(j, c.ids[2], c.ids[3]))
    if (j.faces[f].set >= 0 && j.faces[f].normal.dot(c.geo.normal) > best_align)
      best = j.faces[f].set, best_align = j.faces[f].normal.dot(c.geo.normal);
  for (int f : faces_at(i, c.ids[0], c.ids[1]))
    if (i.faces[f].set >= 0 && -i.faces[f].normal.dot(c.geo.normal) > best_align)
      best = i.faces[f].set, best_align = -i.faces[f].normal.dot(c.geo.normal);
  return best;
}

}  // namespace dda::df3
