#pragma once
// A run that has gone numerically wrong: a step whose solution is not a
// finite number, or that moves a block further than the size of the whole
// model even at the smallest time step. Simulation::step() throws it rather
// than carry on with garbage; the message is one sentence naming the step,
// the time, the block and what to try.
#include <stdexcept>
#include <string>

namespace dda::df {

class RunawayError : public std::runtime_error {
 public:
  RunawayError(const std::string& sentence, int step, double time, int block)
      : std::runtime_error(sentence), step_(step), time_(time), block_(block) {}
  int step() const { return step_; }       // the step that failed (1 = first)
  double time() const { return time_; }    // s, end time of the failed step
  int block() const { return block_; }     // the offending block

 private:
  int step_;
  double time_;
  int block_;
};

}  // namespace dda::df
