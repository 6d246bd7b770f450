#pragma once
// Poses, twists and wrenches packed into one flat array of doubles and read back in the same
// order: how checkpoints store the haptic loop's state (backend/state_arrays.hpp).
#include "util/pose.hpp"

#include <cstddef>
#include <vector>

namespace mssph {

class PosePacker {
 public:
  void add(double v) { values_.push_back(v); }
  void add(const Eigen::Vector3d& v) { values_.insert(values_.end(), {v.x(), v.y(), v.z()}); }
  void add(const Eigen::Quaterniond& q) { values_.insert(values_.end(), {q.x(), q.y(), q.z(), q.w()}); }
  void add(const Pose& p) {
    add(p.position);
    add(p.orientation);
  }
  void add(const Twist& t) {
    add(t.linear);
    add(t.angular);
  }
  void add(const Wrench& w) {
    add(w.force);
    add(w.torque);
  }
  std::vector<double> take() { return std::move(values_); }

 private:
  std::vector<double> values_;
};

// Reads what a PosePacker wrote; the caller checks the array's length first (StateArrays::get).
class PoseUnpacker {
 public:
  explicit PoseUnpacker(const std::vector<double>& values) : values_(values) {}
  double scalar() { return values_[next_++]; }
  Eigen::Vector3d vector() {
    const Eigen::Vector3d v(&values_[next_]);
    next_ += 3;
    return v;
  }
  Eigen::Quaterniond quaternion() {
    const Eigen::Quaterniond q(values_[next_ + 3], values_[next_], values_[next_ + 1], values_[next_ + 2]);
    next_ += 4;
    return q;
  }
  Pose pose() {
    Pose p;
    p.position = vector();
    p.orientation = quaternion();
    return p;
  }
  Twist twist() {
    Twist t;
    t.linear = vector();
    t.angular = vector();
    return t;
  }
  Wrench wrench() {
    Wrench w;
    w.force = vector();
    w.torque = vector();
    return w;
  }

 private:
  const std::vector<double>& values_;
  std::size_t next_ = 0;
};

}  // namespace mssph
