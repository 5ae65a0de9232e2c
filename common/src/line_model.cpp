#include "dda/common/line_model.hpp"

namespace dda {

const char* to_string(PointKind k) {
  switch (k) {
    case PointKind::Fixed: return "fixed";
    case PointKind::Load: return "load";
    case PointKind::Measurement: return "measurement";
    case PointKind::Hole: return "hole";
  }
  return "unknown";
}

}  // namespace dda
