#pragma once
// Earthquake input of the 3D solver: a three-component ground acceleration
// a_g(t) (x east, y north, z up; m/s^2) and how it reaches the blocks, one
// small type per mode behind one interface (as ground_motion.hpp in 2D):
//  * loading: the free blocks feel the motion in the frame of the ground, as
//    the body force -rho a_g(t) added to gravity; the foundation (the fixed
//    blocks) stays where it is;
//  * displacement: the foundation moves with the ground displacement d_g(t),
//    a_g integrated twice from rest; the free blocks feel it only through
//    their contacts.
// For a rigid foundation both give the same motion relative to it.
#include <memory>
#include <string>
#include <vector>

#include "dda/common/geometry3d.hpp"

namespace dda::df3 {

// a_g piecewise linear between samples, zero before the first sample and
// after the last; its velocity and displacement integrated exactly from rest
// at the first sample (so after the last one the ground drifts on at its
// final velocity: a record should end at rest, e.g. baseline corrected).
class GroundMotion3 {
 public:
  // InputError unless the times strictly increase and match the samples.
  GroundMotion3(std::vector<double> t, std::vector<Vec3> a);
  Vec3 acceleration(double t) const;
  Vec3 velocity(double t) const;
  Vec3 displacement(double t) const;
  // (v(t1) - v(t0)) / (t1 - t0): the exact impulse of the step; a(t0) if t1 <= t0.
  Vec3 mean_acceleration(double t0, double t1) const;
  double start() const { return t_.front(); }
  double end() const { return t_.back(); }
  const std::vector<double>& times() const { return t_; }  // the samples' (for the default time step)

 private:
  // Index k of the interval [t_k, t_k+1] holding t (t inside the record).
  std::size_t interval(double t) const;
  std::vector<double> t_;
  std::vector<Vec3> a_, v_, d_;  // at the samples
};

// How the motion enters a step [t, t + dt].
class GroundMotionMode3 {
 public:
  virtual ~GroundMotionMode3() = default;
  virtual std::string name() const = 0;
  // Added to gravity on every free block.
  virtual Vec3 body_acceleration(const GroundMotion3& g, double t, double dt) const = 0;
  // Translation of every fixed block over the step.
  virtual Vec3 foundation_increment(const GroundMotion3& g, double t, double dt) const = 0;
};

class LoadingMode3 final : public GroundMotionMode3 {
 public:
  std::string name() const override { return "loading"; }
  Vec3 body_acceleration(const GroundMotion3& g, double t, double dt) const override {
    return -g.mean_acceleration(t, t + dt);
  }
  Vec3 foundation_increment(const GroundMotion3&, double, double) const override { return Vec3::Zero(); }
};

class DisplacementMode3 final : public GroundMotionMode3 {
 public:
  std::string name() const override { return "displacement"; }
  Vec3 body_acceleration(const GroundMotion3&, double, double) const override { return Vec3::Zero(); }
  Vec3 foundation_increment(const GroundMotion3& g, double t, double dt) const override {
    return g.displacement(t + dt) - g.displacement(t);
  }
};

// Incident: the record is the outcrop motion; it enters as an incident wave
// of half its velocity through the viscous boundary's input faces
// (viscous_boundary3d.hpp; the scenario reader fills
// ViscousBoundary3::incident_velocity from the record). No body force, no
// moving foundation.
class IncidentWaveMode3 final : public GroundMotionMode3 {
 public:
  std::string name() const override { return "incident"; }
  Vec3 body_acceleration(const GroundMotion3&, double, double) const override { return Vec3::Zero(); }
  Vec3 foundation_increment(const GroundMotion3&, double, double) const override { return Vec3::Zero(); }
};

// "loading", "displacement" or "incident"; InputError otherwise.
std::shared_ptr<const GroundMotionMode3> make_ground_motion_mode3(const std::string& name);

// The earthquake of a 3D model: the motion and its mode.
struct GroundInput3 {
  std::shared_ptr<const GroundMotion3> motion;
  std::shared_ptr<const GroundMotionMode3> mode;
};

}  // namespace dda::df3
