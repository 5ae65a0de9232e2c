// A planar section of a 3D fracture model as a 2D line model.
#include "dda/dl/trace_plane.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "builder.hpp"  // detail::format_number
#include "dda/common/error.hpp"
#include "dda/dl/dfn3d.hpp"
#include "dda/dl/polygon3d.hpp"

namespace dda::dl {

using detail::format_number;

namespace {

// Fracture planes closer to parallel to the section than this leave no trace.
constexpr double kParallelSine = 1e-9;

std::string point_text(const Vec3& p) {
  return "(" + format_number(p.x()) + ", " + format_number(p.y()) + ", " + format_number(p.z()) + ")";
}

TraceFrame frame_of(const Vec3& point, const Vec3& unit_normal) {
  if (!point.allFinite()) throw InputError("A trace plane's point must have finite coordinates.");
  TraceFrame f;
  f.origin = point;
  f.n = unit_normal;
  const double h = std::hypot(unit_normal.x(), unit_normal.y());
  f.u = h == 0 ? Vec3(1, 0, 0) : Vec3(-unit_normal.y() / h, unit_normal.x() / h, 0);  // z x n, normalised
  f.v = f.n.cross(f.u).normalized();
  return f;
}

// The line where a fracture's plane meets the section, in (u, v): p0 + t d.
struct Line2 {
  Vec2 p0, d;
};

// Liang-Barsky on a convex counter-clockwise polygon: narrows [t0, t1] to
// the part of the line inside; false if nothing is left.
bool clip_to_convex(const Polygon2& poly, const Line2& line, double& t0, double& t1) {
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2& a = poly[i];
    const Vec2 e = poly[(i + 1) % poly.size()] - a;
    const double g0 = cross(e, line.p0 - a), g1 = cross(e, line.d);  // inside where g0 + t g1 >= 0
    if (g1 == 0) {
      if (g0 < 0) return false;
      continue;
    }
    const double t = -g0 / g1;
    if (g1 > 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (!(t0 < t1)) return false;
  }
  return true;
}

// The parameter range of the fracture on its line; false if it misses the plane.
bool fracture_range(const Fracture3& fr, const TraceFrame& f, const Line2& line, double& t0, double& t1) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  switch (fr.shape) {
    case FractureShape::Plane:
      t0 = -inf;
      t1 = inf;
      return true;
    case FractureShape::Disc: {
      // The line lies in the disc's plane, so its points within the radius of
      // the centre (3D distance; the centre is cn off the section) are the chord.
      const Vec3 rel = fr.centre - f.origin;
      const double cn = f.n.dot(rel);
      const Vec2 w = line.p0 - Vec2(f.u.dot(rel), f.v.dot(rel));
      const double b = w.dot(line.d), disc = b * b - w.squaredNorm() + fr.radius * fr.radius - cn * cn;
      if (!(disc > 0)) return false;
      t0 = -b - std::sqrt(disc);
      t1 = -b + std::sqrt(disc);
      return true;
    }
    case FractureShape::Polygon: {
      // Where the polygon's edges meet the section; a convex polygon meets it
      // in one segment, from the least to the greatest such point.
      const double offset = f.n.dot(f.origin);
      t0 = inf;
      t1 = -inf;
      auto add = [&](const Vec3& p) {
        const double t = (f.to_plane(p) - line.p0).dot(line.d);
        t0 = std::min(t0, t);
        t1 = std::max(t1, t);
      };
      const std::size_t n = fr.vertices.size();
      for (std::size_t i = 0; i < n; ++i) {
        const Vec3 &p = fr.vertices[i], &q = fr.vertices[(i + 1) % n];
        const double dp = f.n.dot(p) - offset, dq = f.n.dot(q) - offset;
        if (dp == 0) add(p);
        if ((dp < 0 && dq > 0) || (dp > 0 && dq < 0)) add(p + (dp / (dp - dq)) * (q - p));
      }
      return t0 < t1;
    }
  }
  return false;
}

// The beds in the section: coordinates along their 2D normal, apparent dip,
// and whether the order turns over.
void section_layers(const FractureModel& model, const TraceFrame& f, LineModel& out, bool& flipped) {
  flipped = false;
  if (model.layers.empty()) return;
  const Vec3& nb = model.bed_normal;
  Vec2 p(nb.dot(f.u), nb.dot(f.v));
  const double s = p.norm();
  if (s < kParallelSine) return;  // the section lies along the beds
  flipped = p.y() < 0;             // the 2D normal must point up (dip within [-90, 90])
  const double sign = flipped ? -1 : 1;
  p *= sign / s;
  out.bedding_dip_deg = rad2deg(std::atan2(-p.x(), p.y()));
  // A bed plane nb . x = w is, in (u, v), p . q = sign (w - nb . origin) / s.
  const double base = nb.dot(f.origin);
  for (const Layer& l : model.layers) {
    Layer m = l;
    m.bottom = sign * ((flipped ? l.top : l.bottom) - base) / s;
    m.top = sign * ((flipped ? l.bottom : l.top) - base) / s;
    out.layers.push_back(m);
  }
  if (flipped) std::reverse(out.layers.begin(), out.layers.end());
}

}  // namespace

TraceFrame trace_frame(const Vec3& point, double dip_deg, double dip_direction_deg) {
  return frame_of(point, normal_from_dip(dip_deg, dip_direction_deg));
}

TraceFrame trace_frame(const Vec3& point, const Vec3& normal) {
  const double len = normal.norm();
  if (!(len > 0) || !std::isfinite(len)) throw InputError("A trace plane's normal must be a finite non-zero vector.");
  return frame_of(point, normal.z() < 0 ? Vec3(-normal / len) : Vec3(normal / len));
}

LineModel trace_section(const FractureModel& model, const TraceFrame& f) {
  validate_box(model.domain, "The fracture model's domain");
  // Sections of closed surfaces are not drawn yet: refusing is better than
  // a section that silently shows the wrong rock.
  if (model.domain_surface)
    throw InputError("A trace plane cannot section a model whose domain is a closed surface (only a box) yet.");
  for (const Excavation3& ex : model.excavations)
    if (ex.surface)
      throw InputError("A trace plane cannot section the closed-surface excavation '" + ex.name + "' yet.");
  const Polygon3 section = plane_in_box(f.n, f.n.dot(f.origin), model.domain);
  if (section.empty())
    throw InputError("The trace plane through " + point_text(f.origin) + " misses the model's domain.");
  const double diag = (model.domain.hi - model.domain.lo).norm();

  LineModel out;
  for (const Vec3& p : section) out.domain.push_back(f.to_plane(p));  // counter-clockwise about n = in (u, v)
  for (const Excavation3& ex : model.excavations) {
    Polygon3 cut = clip_polygon(section, ex.region, 1e-12 * diag);
    remove_duplicate_vertices(cut, 1e-12 * diag);
    if (cut.size() < 3 || polygon_area(cut) <= 1e-12 * diag * diag) continue;
    Polygon2 outline;
    for (const Vec3& p : cut) outline.push_back(f.to_plane(p));
    out.excavations.push_back(std::move(outline));
  }

  bool flipped = false;
  section_layers(model, f, out, flipped);
  const int nlayers = static_cast<int>(model.layers.size());

  for (const Fracture3& fr : model.fractures) {
    // The fracture's plane in (u, v): a U + b V = c.
    const Vec2 ab(fr.normal.dot(f.u), fr.normal.dot(f.v));
    const double sine = ab.norm();
    if (sine < kParallelSine * fr.normal.norm()) continue;
    const double c = fr.offset() - fr.normal.dot(f.origin);
    const Line2 line{c * ab / (sine * sine), Vec2(-ab.y(), ab.x()) / sine};
    double t0 = 0, t1 = 0;
    if (!fracture_range(fr, f, line, t0, t1) || !clip_to_convex(out.domain, line, t0, t1)) continue;
    if (!(t1 - t0 > 1e-12 * diag)) continue;
    JointLine jl;
    jl.a = line.p0 + t0 * line.d;
    jl.b = line.p0 + t1 * line.d;
    jl.set = fr.set;
    jl.kind = fr.kind;
    jl.layer = out.layers.empty() || fr.layer < 0 ? -1 : (flipped ? nlayers - 1 - fr.layer : fr.layer);
    out.lines.push_back(jl);
  }
  out.sets = model.sets;
  out.provenance = model.provenance;
  return out;
}

}  // namespace dda::dl
