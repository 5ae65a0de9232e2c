#include "dda/analysis/backfit.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "dda/common/error.hpp"
#include "dda/common/geometry.hpp"

namespace dda::analysis {

namespace {

struct Misfit {
  double sse = 0.0;
  int count = 0;
  double path = 0.0;  // path length travelled (m)
  double rms() const { return count > 0 ? std::sqrt(sse / count) : 0.0; }
};

double error2(const MeasuredHistory &m, std::size_t j, const Vec3 &u, const Vec3 &ref) {
  if (m.vector_form) return (u - m.u[j]).squaredNorm();
  const double d = u.dot(ref) - m.s[j];
  return d * d;
}

// Advances `sim` to time `t_end`, adding the misfit at measured samples with
// t_begin < t_j <= t_end (index `next` moves along).
void advance(SlidingSimulator &sim, double t_end, const MeasuredHistory &m, std::size_t &next, Misfit &out) {
  const Vec3 ref = sim.reference_direction();
  const double dt = sim.dt();
  // Time is a sum of steps, so it reaches t_end only to within rounding: one
  // tolerance, far below any step, decides both where the loop stops and
  // which samples fall in this segment (a sample at a segment boundary
  // belongs to the segment that ends there, whatever the step).
  const double tol = 1e-9 * std::max(1.0, std::abs(t_end));
  while (sim.state().t < t_end - tol) {
    const SlidingState before = sim.state();
    const double h = std::min(dt, t_end - before.t);
    sim.step(h);
    const SlidingState &after = sim.state();
    out.path += (after.u - before.u).norm();
    while (next < m.t.size() && m.t[next] <= after.t + tol) {
      const double w = (m.t[next] - before.t) / (after.t - before.t);
      const Vec3 u = (1.0 - w) * before.u + w * after.u;
      out.sse += error2(m, next, u, ref);
      ++out.count;
      ++next;
    }
    if (sim.finished()) {
      // Lifted off: the block is gone; the remaining samples compare to its
      // last position.
      while (next < m.t.size() && m.t[next] <= t_end + tol) {
        out.sse += error2(m, next, after.u, ref);
        ++out.count;
        ++next;
      }
      return;
    }
  }
  // Samples within the tolerance past the last step's end (at t_end).
  while (next < m.t.size() && m.t[next] <= t_end + tol) {
    out.sse += error2(m, next, sim.state().u, ref);
    ++out.count;
    ++next;
  }
}

void set_friction(SlidingSimulator &sim, const FrictionLaw &law) {
  for (auto &f : sim.model().friction) f = law;
}

// Samples at or before the start time compare to the start state.
std::size_t initial_samples(const SlidingSimulator &sim, const MeasuredHistory &m, Misfit &out) {
  std::size_t next = 0;
  while (next < m.t.size() && m.t[next] <= sim.state().t + 1e-9 * std::max(1.0, std::abs(sim.state().t))) {
    out.sse += error2(m, next, sim.state().u, sim.reference_direction());
    ++out.count;
    ++next;
  }
  return next;
}

void check_measured(const MeasuredHistory &m) {
  if (m.t.size() < 2) throw InputError("Back-analysis: the measured history needs at least two samples.");
  if (m.vector_form ? m.u.size() != m.t.size() : m.s.size() != m.t.size())
    throw InputError("Back-analysis: the measured history has mismatched columns.");
}

}  // namespace

double history_misfit(const SlidingModel &model, const MeasuredHistory &measured, double dt) {
  check_measured(measured);
  SlidingSimulator sim(model, dt);
  Misfit mf;
  std::size_t next = initial_samples(sim, measured, mf);
  advance(sim, measured.t.back(), measured, next, mf);
  return mf.rms();
}

BackfitResult backfit(const SlidingModel &model, const MeasuredHistory &measured, const BackfitOptions &o) {
  check_measured(measured);
  if (!(o.phi_min >= 0.0 && o.phi_min < o.phi_max && o.phi_max < 90.0))
    throw InputError(
        "Back-analysis: the friction search range must satisfy 0 "
        "<= min < max < 90 degrees.");
  const double t_last = measured.t.back();
  std::vector<double> bounds{0.0};
  for (double b : o.breaks) {
    if (!(b > bounds.back()) || !(b < t_last))
      throw InputError(
          "Back-analysis: segment boundaries must increase and "
          "lie inside the measured time span.");
    bounds.push_back(b);
  }
  bounds.push_back(t_last);

  BackfitResult result;
  SlidingSimulator sim(model, o.dt);
  set_friction(sim, FrictionLaw::constant_angle(o.phi_max));
  Misfit total;
  std::size_t next = initial_samples(sim, measured, total);
  const double gr = (std::sqrt(5.0) - 1.0) / 2.0;
  for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
    const double t0 = bounds[k], t1 = bounds[k + 1];
    auto trial = [&](double phi) {
      SlidingSimulator copy = sim;
      set_friction(copy, FrictionLaw::constant_angle(phi));
      std::size_t nx = next;
      Misfit mf;
      advance(copy, t1, measured, nx, mf);
      return mf.rms();
    };
    // Golden-section search.
    double a = o.phi_min, b = o.phi_max;
    double c = b - gr * (b - a), d = a + gr * (b - a);
    double fc = trial(c), fd = trial(d);
    while (b - a > o.tolerance_deg) {
      if (fc <= fd) {
        b = d;
        d = c;
        fd = fc;
        c = b - gr * (b - a);
        fc = trial(c);
      } else {
        a = c;
        c = d;
        fc = fd;
        d = a + gr * (b - a);
        fd = trial(d);
      }
    }
    const double phi = 0.5 * (a + b);
    set_friction(sim, FrictionLaw::constant_angle(phi));
    Misfit seg;
    advance(sim, t1, measured, next, seg);
    total.sse += seg.sse;
    total.count += seg.count;
    SegmentFit s;
    s.t0 = t0;
    s.t1 = t1;
    s.phi_deg = phi;
    s.mu = std::tan(deg2rad(phi));
    s.rms = seg.rms();
    s.samples = seg.count;
    s.mean_speed = seg.path / (t1 - t0);
    result.segments.push_back(s);
  }
  result.rms = total.rms();

  // Regression of mu on ln(v / v_ref) over the segments.
  std::vector<std::array<double, 2>> pts;
  for (const auto &s : result.segments)
    if (s.mean_speed > 0.0) pts.push_back({std::log(s.mean_speed / o.v_ref), s.mu});
  if (pts.size() >= 2) {
    double sx = 0, sy = 0;
    for (const auto &p : pts) {
      sx += p[0];
      sy += p[1];
    }
    const double n = static_cast<double>(pts.size());
    const double mx = sx / n, my = sy / n;
    double sxx = 0, sxy = 0, syy = 0;
    for (const auto &p : pts) {
      sxx += (p[0] - mx) * (p[0] - mx);
      sxy += (p[0] - mx) * (p[1] - my);
      syy += (p[1] - my) * (p[1] - my);
    }
    if (sxx > 0.0) {
      auto &r = result.regression;
      r.b = sxy / sxx;
      r.a = my - r.b * mx;
      double ssr = 0;
      for (const auto &p : pts) ssr += std::pow(p[1] - r.a - r.b * p[0], 2);
      r.r2 = syy > 0.0 ? 1.0 - ssr / syy : 1.0;
      r.valid = true;
    }
  }

  if (o.fit_log_velocity) {
    auto misfit = [&](const std::array<double, 2> &p) {
      SlidingModel m = model;
      for (auto &f : m.friction) f = FrictionLaw::log_velocity(p[0], p[1], o.v_ref, o.v_min);
      return history_misfit(m, measured, o.dt);
    };
    // Nelder-Mead in (a, b).
    std::array<double, 2> start{0.0, 0.0};
    if (result.regression.valid) {
      start = {result.regression.a, result.regression.b};
    } else {
      double mu = 0;
      for (const auto &s : result.segments) mu += s.mu;
      start = {mu / static_cast<double>(result.segments.size()), 0.0};
    }
    const double start_misfit = misfit(start);
    std::array<std::array<double, 2>, 3> x{start, start, start};
    std::array<double, 3> f{};
    // Two passes: the second restarts from the best point with a fresh
    // simplex (a and b are correlated; one pass can stall in the valley).
    for (int pass = 0; pass < 2; ++pass) {
      if (pass == 1) {
        std::size_t best = 0;
        for (std::size_t i = 1; i < 3; ++i)
          if (f[i] < f[best]) best = i;
        x = {x[best], x[best], x[best]};
      }
      x[1][0] += 0.02;
      x[2][1] += 0.005;
      f = {misfit(x[0]), misfit(x[1]), misfit(x[2])};
      for (int it = 0; it < 400; ++it) {
        std::array<int, 3> idx{0, 1, 2};
        std::sort(idx.begin(), idx.end(),
                  [&](int i, int j) { return f[static_cast<std::size_t>(i)] < f[static_cast<std::size_t>(j)]; });
        auto X = [&](int i) -> std::array<double, 2> & {
          return x[static_cast<std::size_t>(idx[static_cast<std::size_t>(i)])];
        };
        auto F = [&](int i) -> double & { return f[static_cast<std::size_t>(idx[static_cast<std::size_t>(i)])]; };
        const double size = std::max(std::abs(X(1)[0] - X(0)[0]) + std::abs(X(2)[0] - X(0)[0]),
                                     std::abs(X(1)[1] - X(0)[1]) + std::abs(X(2)[1] - X(0)[1]));
        if (size < 1e-7) break;
        const std::array<double, 2> cen{0.5 * (X(0)[0] + X(1)[0]), 0.5 * (X(0)[1] + X(1)[1])};
        auto along = [&](double t) {
          return std::array<double, 2>{cen[0] + t * (X(2)[0] - cen[0]), cen[1] + t * (X(2)[1] - cen[1])};
        };
        const auto xr = along(-1.0);
        const double fr = misfit(xr);
        if (fr < F(0)) {
          const auto xe = along(-2.0);
          const double fe = misfit(xe);
          if (fe < fr) {
            X(2) = xe;
            F(2) = fe;
          } else {
            X(2) = xr;
            F(2) = fr;
          }
        } else if (fr < F(1)) {
          X(2) = xr;
          F(2) = fr;
        } else {
          const auto xc = along(fr < F(2) ? -0.5 : 0.5);
          const double fcn = misfit(xc);
          if (fcn < std::min(fr, F(2))) {
            X(2) = xc;
            F(2) = fcn;
          } else {
            for (int i = 1; i < 3; ++i) {
              X(i) = {X(0)[0] + 0.5 * (X(i)[0] - X(0)[0]), X(0)[1] + 0.5 * (X(i)[1] - X(0)[1])};
              F(i) = misfit(X(i));
            }
          }
        }
      }
    }
    std::size_t best = 0;
    for (std::size_t i = 1; i < 3; ++i)
      if (f[i] < f[best]) best = i;
    result.direct.a = x[best][0];
    result.direct.b = x[best][1];
    result.direct.rms = f[best];
    result.direct.valid = true;
    result.direct.stalled = !(f[best] < start_misfit * (1.0 - 1e-9));
  }
  return result;
}

}  // namespace dda::analysis
