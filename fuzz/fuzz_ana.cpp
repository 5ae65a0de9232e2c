// DDA for Windows analysis files, .ana (df::import_ana), read against the
// blocks `dda dl` + `dda dc` make of tests/data/df_pushblock.geo: a base and
// a block on it, with the geometry's fixed, load and measured points.
#include "dda/common/block_shape.hpp"
#include "dda/common/geometry.hpp"
#include "dda/df/io/import_ana.hpp"
#include "fuzz_support.hpp"

namespace {

dda::Block rectangle_block(double x0, double y0, double w, double h, int set) {
  return dda::make_block({{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}}, set);
}

dda::BlockModel pushblock_blocks() {
  dda::BlockModel m;
  m.sets = {{"type1", "geo"}, {"type2", "geo"}};
  m.blocks.push_back(rectangle_block(0, 0, 4, 1, 0));
  dda::Block top = rectangle_block(1.5, 1, 1, 1, 1);
  top.edge_set[0] = 0;
  m.blocks.push_back(top);
  m.points = {{{"fixed_1", dda::PointKind::Fixed, {0.5, 0.5}}, 0},
              {{"fixed_2", dda::PointKind::Fixed, {3.5, 0.5}}, 0},
              {{"load_1", dda::PointKind::Load, {2, 1.5}}, 1},
              {{"measured_1", dda::PointKind::Measurement, {2, 1.5}}, 1}};
  return m;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const dda::BlockModel blocks = pushblock_blocks();
  const std::string text = dda::fuzz::as_text(data, size);
  dda::fuzz::refuse_only_with_input_errors([&] { dda::df::import_ana(text, "m.ana", blocks, "b.h5"); });
  return 0;
}
