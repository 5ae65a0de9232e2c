#pragma once
// dda newmark --ky: Newmark analyses of a series of records at SLAMMER's
// level (rigid, decoupled and coupled; both polarities), with the records'
// intensity measures and the empirical regressions, one table row per record
// and polarity (docs/analytical.md, "Newmark analyses of records").
#include <string>
#include <vector>

#include "analysis_options.hpp"
#include "dda/analysis/intensity_measures.hpp"
#include "dda/analysis/shear_beam.hpp"

namespace dda::cli {

struct RecordsAnalysis {
  double ky = 0.0;  // yield coefficient (g)
  bool rigid = true, decoupled = false, coupled = false;
  bool normal = true, inverse = true;     // polarities
  analysis::ShearBeam beam;               // small-strain Ts and damping
  double height = 0.0;                    // m, for the equivalent-linear strain
  analysis::EquivalentLinearCurve curve;  // used when reference_strain > 0
  double magnitude = 0.0;                 // for Bray and Travasarou (2007)
  bool has_magnitude = false;
};

struct PolarityResult {
  std::string polarity;                                // "normal" or "inverse"
  double rigid = 0.0, decoupled = 0.0, coupled = 0.0;  // m
  double kmax = 0.0;                                   // g, peak |HEA| (decoupled)
};

struct RecordResult {
  std::string path;
  double dt = 0.0;
  std::size_t samples = 0;
  analysis::IntensityMeasures im;
  analysis::ShearBeam beam;  // as used (equivalent-linear when asked)
  double modulus_ratio = 1.0, effective_strain = 0.0;
  double sa_bt = 0.0;  // Sa(1.5 Ts) (m/s^2), PGA for Ts < 0.05 s
  std::vector<PolarityResult> polarities;
};

// "rigid,coupled", "all", ...; InputError naming --method otherwise.
void parse_methods(const std::string& text, RecordsAnalysis& a);
// "normal", "inverse" or "both".
void parse_polarity(const std::string& text, RecordsAnalysis& a);
// The record files of the arguments: files as given, a folder's regular
// files (not hidden) in name order. InputError for a missing path or an empty folder.
std::vector<std::string> expand_record_paths(const std::vector<std::string>& args);

// Every record, on the machine's cores (results in the order of `paths`);
// the first failing record's InputError (by order) is thrown.
std::vector<RecordResult> analyse_records(const std::vector<std::string>& paths, const RecordOptions& record,
                                          const RecordsAnalysis& analysis);

// The table as CSV: one row per record and polarity (docs/analytical.md).
std::string records_table_csv(const std::vector<RecordResult>& results, const RecordsAnalysis& analysis);

}  // namespace dda::cli
