#pragma once
// A model history against a reference solution (`dda compare`, the seed
// report's Figure 13): the reference is interpolated linearly at the model's
// sample times inside its time span, and the relative error is
//   e(t) = (u_model(t) - u_ref(t)) / max(|u_ref(t)|, floor),
// the floor keeping e finite where the reference is still near zero (at the
// start of a sliding history); `floor` defaults to 1 % of max |u_ref|. The
// final error is the plain (u_model - u_ref) / |u_ref| at the last compared
// time.
#include <vector>

namespace dda::analysis {

struct SeriesComparison {
  std::vector<double> t, model, reference, difference, relative;
  double floor = 0;               // the floor used
  double final_relative = 0;      // at t.back(); 0 when the reference is 0 there
  double max_abs_difference = 0;
  double rms_difference = 0;
};

// `model_t` and `reference_t` increase; `floor` <= 0 picks the default.
// InputError when the two histories share no time (a model sample inside
// the reference span, 1e-9 relative tolerance at the ends).
SeriesComparison compare_series(const std::vector<double>& model_t, const std::vector<double>& model_u,
                                const std::vector<double>& reference_t, const std::vector<double>& reference_u,
                                double floor = 0);

}  // namespace dda::analysis
