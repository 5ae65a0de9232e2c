#pragma once
// A double as the shortest text that reads back as the same double (and
// "" for NaN, the summary's empty cell): what summary.csv, the case
// documents and the case records hold, so that a study run twice, or once
// locally and once under MPI, gives the same text value for value.
#include <string>

namespace dda::study {

std::string round_trip(double v);

}  // namespace dda::study
