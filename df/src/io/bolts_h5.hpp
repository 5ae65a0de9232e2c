#pragma once
// Rock bolts in the results files of both dimensions (layout in
// docs/formats.md): /bolts, their histories, and <checkpoint>/bolts, their
// states (bolt_law.hpp). Private to DF.
#include <cstdint>
#include <string>
#include <vector>

#include "dda/common/h5_util.hpp"
#include "dda/df/core/bolt_law.hpp"
#include "io/results_h5_util.hpp"

namespace dda::df::h5io {

// /bolts: names, then time, force, length (samples, bolts) and broken.
// `force_what` describes the force column (2D: per unit thickness).
void write_bolt_series(h5::Writer& w, const std::vector<std::string>& names,
                       const std::vector<std::vector<BoltSample>>& histories, const std::string& force_what);
// The inverse, strict about the shapes.
void read_bolt_series(const h5::Reader& r, std::vector<std::string>& names,
                      std::vector<std::vector<BoltSample>>& histories);

// <checkpoint>/bolts: every bolt's ends, initial length, force and state.
template <int dim>
void write_bolt_states(h5::Writer& w, hid_t checkpoint, const std::vector<BoltStateOf<dim>>& states) {
  h5::Id g = subgroup(checkpoint, "bolts");
  std::vector<double> anchor, head, rest, force;
  std::vector<std::int32_t> broken;
  for (const BoltStateOf<dim>& b : states) {
    anchor.insert(anchor.end(), b.anchor.data(), b.anchor.data() + dim);
    head.insert(head.end(), b.head.data(), b.head.data() + dim);
    rest.push_back(b.rest_length);
    force.push_back(b.force);
    broken.push_back(b.broken ? 1 : 0);
  }
  const hsize_t n = states.size();
  w.f64(g.get(), "anchor", anchor, {n, dim}, "m", "current anchor end of each bolt");
  w.f64(g.get(), "head", head, {n, dim}, "m", "current head end of each bolt");
  w.f64(g.get(), "rest_length", rest, {n}, "m", "initial length L0");
  w.f64(g.get(), "force", force, {n}, "N", "axial force, tension positive");
  w.i32(g.get(), "broken", broken, "", "1 once broken");
}

// The inverse of write_bolt_states, `group` being "<checkpoint>/bolts/".
template <int dim>
std::vector<BoltStateOf<dim>> read_bolt_states(const h5::Reader& r, const std::string& group) {
  const std::size_t n = rows_of(r, group + "anchor");
  const std::vector<double> anchor = read_f64(r, group + "anchor", {n, dim}),
                            head = read_f64(r, group + "head", {n, dim}),
                            rest = read_f64(r, group + "rest_length", {n}), force = read_f64(r, group + "force", {n});
  const std::vector<std::int64_t> broken = read_i64(r, group + "broken", n);
  std::vector<BoltStateOf<dim>> out(n);
  for (std::size_t k = 0; k < n; ++k) {
    using Point = typename BoltStateOf<dim>::Point;
    out[k].anchor = Eigen::Map<const Point>(anchor.data() + dim * k);
    out[k].head = Eigen::Map<const Point>(head.data() + dim * k);
    out[k].rest_length = rest[k];
    out[k].force = force[k];
    out[k].broken = broken[k] != 0;
  }
  return out;
}

}  // namespace dda::df::h5io
