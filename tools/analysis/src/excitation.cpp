#include "dda/analysis/excitation.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "dda/common/error.hpp"

namespace dda::analysis {

InputMeaning parse_input_meaning(const std::string& text, const std::string& what) {
  std::string s = text;
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (s == "ground") return InputMeaning::ground;
  if (s == "body") return InputMeaning::body;
  throw InputError(what + ": '" + text + "' is neither ground nor body.");
}

Excitation excitation_from_record(std::shared_ptr<const AccelRecord> record, InputMeaning meaning) {
  Excitation e;
  const double sign = meaning == InputMeaning::ground ? -1.0 : 1.0;
  e.duration = record->t.empty() ? 0.0 : record->t.back();
  e.description = std::string(meaning == InputMeaning::ground ? "ground" : "body") + " acceleration record " +
                  record->source;
  e.body = [record, sign](double t) -> Vec3 { return sign * record->at(t); };
  return e;
}

Excitation sinusoid(const Vec3& direction, double amplitude, double omega, double ramp, InputMeaning meaning) {
  Excitation e;
  const double sign = meaning == InputMeaning::ground ? -1.0 : 1.0;
  const Vec3 d = direction.normalized();
  std::ostringstream s;
  s << (meaning == InputMeaning::ground ? "ground" : "body") << " acceleration " << amplitude << " sin(" << omega
    << " t) m/s^2 along (" << d.x() << ", " << d.y() << ", " << d.z() << ")";
  if (ramp > 0) s << ", ramped up over " << ramp << " s";
  e.description = s.str();
  e.body = [=](double t) -> Vec3 {
    const double w = ramp > 0.0 ? std::clamp(t / ramp, 0.0, 1.0) : 1.0;
    return sign * w * amplitude * std::sin(omega * t) * d;
  };
  return e;
}

Excitation no_input() {
  Excitation e;
  e.description = "gravity alone";
  e.body = [](double) -> Vec3 { return Vec3::Zero(); };
  return e;
}

}  // namespace dda::analysis
