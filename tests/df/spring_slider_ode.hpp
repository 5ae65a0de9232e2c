#pragma once
// An integration of the spring-slider's equations of motion written
// independently of the solver (fixed-step classical Runge-Kutta), the
// reference the friction-instability tests compare DDA with:
//
//   m x'' = k (x_d(t) - x) - N mu(V, s),   x_d = u0 + vd t (the load point),
//   s' = rates(V, s)                        (the law's state, e.g. theta),
//
// x the slider's displacement and V = x'. A law with static friction
// (`sticks`) holds the slider while the spring's pull is at most
// N mu(0, s), and it sticks again when V falls to 0; a law without it
// (rate and state, whose regularised mu(V) is odd in V) slides always.
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

namespace dda::df::test {

struct SliderOde {
  double m = 1000, k = 1e5, n = 9810, vd = 1e-3, u0 = 0;
  double v_start = 0;  // the slider's speed at t = 0
  bool sticks = false;
  std::array<double, 2> state0{0, 0};
  // Friction coefficient at speed V (signed for laws that do not stick).
  std::function<double(double v, const std::array<double, 2>& s)> mu;
  // d(state)/dt; default none.
  std::function<std::array<double, 2>(double v, const std::array<double, 2>& s)> rates;
};

struct OdeSample {
  double t, x, v, spring_force;
};

inline std::vector<OdeSample> integrate(const SliderOde& o, double t_end, double h, double every) {
  struct Y {
    double x, v;
    std::array<double, 2> s;
  };
  auto spring = [&](double t, double x) { return o.k * (o.u0 + o.vd * t - x); };
  auto deriv = [&](double t, const Y& y) {
    Y d{y.v, (spring(t, y.x) - o.n * o.mu(y.v, y.s)) / o.m, {0, 0}};
    if (o.rates) d.s = o.rates(y.v, y.s);
    return d;
  };
  auto add = [](const Y& y, const Y& d, double c) {
    return Y{y.x + c * d.x, y.v + c * d.v, {y.s[0] + c * d.s[0], y.s[1] + c * d.s[1]}};
  };
  Y y{0, o.v_start, o.state0};
  bool stuck = o.sticks && o.v_start <= 0;
  std::vector<OdeSample> out{{0, 0, o.v_start, spring(0, 0)}};
  double next = every;
  const long steps = std::lround(t_end / h);
  for (long i = 0; i < steps; ++i) {
    const double t = i * h;
    if (stuck) {
      // Held: nothing moves but the load point; the state may still evolve.
      if (spring(t, y.x) > o.n * o.mu(0, y.s)) stuck = false;
      else if (o.rates) {
        const std::array<double, 2> r = o.rates(0, y.s);
        y.s = {y.s[0] + h * r[0], y.s[1] + h * r[1]};
      }
    }
    if (!stuck) {
      const Y k1 = deriv(t, y), k2 = deriv(t + h / 2, add(y, k1, h / 2)), k3 = deriv(t + h / 2, add(y, k2, h / 2)),
              k4 = deriv(t + h, add(y, k3, h));
      Y n = y;
      n.x += h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x);
      n.v += h / 6 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v);
      for (int j = 0; j < 2; ++j) n.s[j] += h / 6 * (k1.s[j] + 2 * k2.s[j] + 2 * k3.s[j] + k4.s[j]);
      if (o.sticks && n.v <= 0) {
        // Stuck again within the step: V reached 0 (the step is short
        // enough that where exactly does not matter at the tests' accuracy).
        n.v = 0;
        stuck = true;
      }
      y = n;
    }
    if ((i + 1) * h >= next - 1e-12) {
      out.push_back({(i + 1) * h, y.x, y.v, spring((i + 1) * h, y.x)});
      next += every;
    }
  }
  return out;
}

}  // namespace dda::df::test
