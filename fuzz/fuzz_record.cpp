// Earthquake records: every input is parsed both as CSV and as PEER AT2
// (the two parsers of read_record), one and three components alike.
#include "dda/common/record.hpp"
#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text = dda::fuzz::as_text(data, size);
  dda::RecordReadOptions options;
  options.units = dda::AccelUnits::g;
  dda::fuzz::refuse_only_with_input_errors([&] { dda::parse_record_csv(text, "r.csv", options); });
  dda::fuzz::refuse_only_with_input_errors([&] { dda::parse_record_at2(text, "r.at2", options); });
  return 0;
}
