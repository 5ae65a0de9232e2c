#pragma once
// DDA for Windows analysis files (`.ana`, the XML form `<Berkeley:DDA>` with
// `<Analysis>`): control parameters, block materials and joint properties of
// a model whose geometry came from the matching `.geo` (`dda dl model.geo`,
// then `dda dc`). The mapping is documented in docs/formats.md.
//
// Joint types: `<Jointproperties type="N">` applies to the joint set named
// `typeN` (the name the .geo importer gives the joints of type N); edges of
// any other set (the domain boundary, `fixed` lines) take the properties of
// the lowest type. Load points: the k-th `<Loadpoint>` is the force history
// (t fx fy records, piecewise linear) of the geometry's k-th load point.
#include <string>
#include <vector>

#include "dda/common/block_model.hpp"
#include "dda/df/io/scenario.hpp"

namespace dda::df {

struct AnaImport {
  DfScenario scenario;                // ready for build_model (geometry = the blocks)
  std::vector<std::string> warnings;  // settings of the old program that have no effect here
};

// Parses `text` (the whole .ana file; `label` names it in messages) against
// `blocks`. InputError of one sentence, naming the file and line, for
// anything that cannot be imported.
AnaImport import_ana(const std::string& text, const std::string& label, const BlockModel& blocks,
                     const std::string& blocks_path);

// Whether a file name ends in .ana (any case).
bool is_ana_path(const std::string& path);

}  // namespace dda::df
