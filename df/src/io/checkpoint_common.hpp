#pragma once
// What the /checkpoint groups of the 2D and 3D results files share
// (checkpoint_h5.cpp, checkpoint3d_h5.cpp): the group's clock attributes,
// per-contact columns, tables of a known shape, rows of points and ragged
// per-contact values (a friction law's memory). What differs by dimension,
// the blocks' and contacts' own fields, stays in those two files. Private to
// DF; the layouts are in docs/formats.md.
#include <cstdint>
#include <string>
#include <vector>

#include "dda/common/geometry.hpp"
#include "dda/common/geometry3d.hpp"
#include "dda/common/h5_util.hpp"

namespace dda::df::h5io {

// The attributes time, dt, step_count and started of the group `g`; the
// caller adds its own and the description after them.
void write_checkpoint_clock(h5::Writer& w, hid_t g, double time, double dt, int step_count, bool started);

struct CheckpointClock {
  double time = 0;
  double dt = 0;
  int step_count = 0;    // 0 if the caller did not ask for it
  bool started = true;   // files written before the attribute had started
};
// Checks that /checkpoint is a group and reads its clock. `with_step_count`:
// the step count is required too (the 3D file takes it from its log).
CheckpointClock read_checkpoint_clock(const h5::Reader& r, bool with_step_count);

// One value per contact of `get(contact)`, as int32 or float64.
template <class Contact, class Get>
std::vector<std::int32_t> contact_ints(const std::vector<Contact>& cs, Get get) {
  std::vector<std::int32_t> out;
  out.reserve(cs.size());
  for (const Contact& c : cs) out.push_back(static_cast<std::int32_t>(get(c)));
  return out;
}
template <class Contact, class Get>
std::vector<double> contact_reals(const std::vector<Contact>& cs, Get get) {
  std::vector<double> out;
  out.reserve(cs.size());
  for (const Contact& c : cs) out.push_back(get(c));
  return out;
}

// The float64 dataset `name` of n rows of `cols` numbers (one number a row
// for cols 1: shape (n,)), row after row; fails naming the shape it needs.
std::vector<double> checkpoint_table(const h5::Reader& r, const std::string& name, std::size_t n, std::size_t cols);

// The rows of points of an (n, 2) or (n, 3) dataset; `n` is its own row
// count unless the model fixes it.
std::vector<Vec2> read_points2(const h5::Reader& r, const std::string& name, std::size_t n);
std::vector<Vec2> read_points2(const h5::Reader& r, const std::string& name);
std::vector<Vec3> read_points3(const h5::Reader& r, const std::string& name);

// Values of varying count per contact, stored as `count_name` (int32, one per
// contact) and `values_name` (float64, all contacts' values in contact order).
template <class Contact, class Values>
void write_ragged(h5::Writer& w, hid_t g, const std::vector<Contact>& cs, Values values, const char* count_name,
                  const char* count_what, const char* values_name, const char* values_what) {
  std::vector<double> all;
  std::vector<std::int32_t> count;
  count.reserve(cs.size());
  for (const Contact& c : cs) {
    const std::vector<double>& v = values(c);
    all.insert(all.end(), v.begin(), v.end());
    count.push_back(static_cast<std::int32_t>(v.size()));
  }
  w.i32(g, count_name, count, "", count_what);
  w.f64(g, values_name, all, {all.size()}, "", values_what);
}

// The inverse, one vector per contact: `counts` are the stored counts (each
// at least `min_count`), `dir` the group's path ending in '/'.
std::vector<std::vector<double>> read_ragged(const h5::Reader& r, const std::string& dir,
                                             const std::vector<std::int64_t>& counts, const std::string& count_name,
                                             const std::string& values_name, std::int64_t min_count);

}  // namespace dda::df::h5io
