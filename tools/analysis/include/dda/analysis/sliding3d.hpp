#pragma once
// The seed report's 3D analytical solution of dynamic sliding of a rigid block
// on one plane (single face) or two planes (double face, tetrahedral wedge).
//
// Per unit mass, at every evaluation: r = (0,0,-g) + b(t) (excitation.hpp).
//  * single face, upward normal n: normal reaction N = -r.n, driving part
//    m = r + N n (r projected on the plane);
//  * double face: I = n1 x n2, line unit vector e = I/|I|, driving part
//    m = (r.e) e, reactions N1 = -((r x n2).I)/|I|^2, N2 = ((r x n1).I)/|I|^2
//    (so that r + N1 n1 + N2 n2 = m);
//  * friction resistance F = mu1 N1 [+ mu2 N2]; if the block moves, f = F v/|v|,
//    else f = F m/|m| capped at |m| (f = m: it stays);
//  * acceleration s = m - f.
// Integration as in the seed: S = (s_start + s_end)/2 with the friction state
// of the start of the step, v += S dt, u += v_old dt + S dt^2/2; the block
// stops when its velocity would turn by more than 90 degrees within a step.
// Except for a slow block (0 < |v| <= F dt): there friction acts against the
// velocity at the end of the step, z = v + M dt (M the mean driving part):
// it stops if |z| <= F dt, else v = z (1 - F dt/|z|). On a line this is the
// seed's step; off a line the seed's rule made a starting block stutter
// (SlidingSimulator::step explains it).
//
// Contact changes: a negative reaction on one plane of a wedge means the block
// leaves that plane; it continues on the other plane alone (single face), and
// comes back to double-face sliding when it moves into the lost plane again
// (inelastically). A negative reaction in single-face sliding is lift-off:
// the analysis ends there (it is reported). Gaps are measured from the start
// position, where the block touches its planes.
#include <string>
#include <vector>

#include "dda/analysis/excitation.hpp"
#include "dda/analysis/friction.hpp"
#include "dda/analysis/orientation.hpp"

namespace dda::analysis {

enum class ContactMode { double_face, face1, face2, lifted };
const char* mode_name(ContactMode mode);

struct SlidingModel {
  std::vector<Plane> planes;           // one (single face) or two (wedge)
  std::vector<FrictionLaw> friction;   // one per plane
  Excitation input;
  double gravity = 9.81;
  // Water force on each plane per unit weight (U_i / W, >= 0; empty or
  // zeros: dry): pore pressure on the sliding planes, constant through the
  // shaking (hydrostatic), along each plane's upward normal, so the normal
  // reactions become effective ones (e.g. `dda wedge --water`'s forces).
  std::vector<double> water;
};

struct SlidingState {
  double t = 0.0;
  Vec3 u = Vec3::Zero();
  Vec3 v = Vec3::Zero();
  ContactMode mode = ContactMode::face1;
  double n1 = 0.0, n2 = 0.0;  // normal reactions per unit mass at t (m/s^2)
};

struct SlidingEvent {
  double t = 0.0;
  std::string what;
};

class SlidingSimulator {
 public:
  // InputError if the planes are not one or two, parallel, or friction is
  // missing; dt > 0.
  SlidingSimulator(SlidingModel model, double dt);

  // Advances by h (the simulator's dt if h <= 0).
  void step(double h = 0.0);
  bool finished() const { return state_.mode == ContactMode::lifted; }
  const SlidingState& state() const { return state_; }
  const std::vector<SlidingEvent>& events() const { return events_; }
  const SlidingModel& model() const { return model_; }
  SlidingModel& model() { return model_; }
  double dt() const { return dt_; }
  // Reference sliding direction (unit): down the line of intersection for a
  // wedge, down the dip for a single face.
  Vec3 reference_direction() const { return reference_; }

 private:
  struct Eval {
    Vec3 s = Vec3::Zero();
    Vec3 m = Vec3::Zero();  // driving part (before friction)
    double cap = 0.0;       // friction capacity F
    double n1 = 0.0, n2 = 0.0;
    bool feasible = true;
  };
  Eval evaluate(double t, const Vec3& v, ContactMode mode) const;
  void settle_mode();
  void constrain();

  SlidingModel model_;
  double dt_;
  SlidingState state_;
  std::vector<SlidingEvent> events_;
  Vec3 n1_, n2_, e_;  // normals and line unit vector (e_ only for wedges)
  Vec3 water_ = Vec3::Zero();  // g sum U_i n_i per unit mass (SlidingModel::water)
  Vec3 reference_;
};

struct SlidingRun {
  std::vector<SlidingState> samples;  // every `every`-th step, plus the last
  std::vector<SlidingEvent> events;
  Vec3 reference = Vec3::Zero();
};
SlidingRun run_sliding(const SlidingModel& model, double dt, double duration, int every = 1);

}  // namespace dda::analysis
