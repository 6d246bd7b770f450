#include "haptics/pose_track.hpp"

#include <algorithm>

namespace mssph {

PoseTrack::PoseTrack(std::vector<double> time, std::vector<Pose> pose)
    : time_(std::move(time)), pose_(std::move(pose)) {}

PoseTrack::Sample PoseTrack::at(double t) const {
  if (t <= time_.front()) return {pose_.front(), Twist{}};
  if (t >= time_.back()) return {pose_.back(), Twist{}};
  // Segment [t_i, t_i+1) with t_i <= t < t_i+1: a sample at exactly t_i reproduces pose i.
  const std::size_t next = static_cast<std::size_t>(std::upper_bound(time_.begin(), time_.end(), t) - time_.begin());
  const std::size_t i = next - 1;
  const double span = time_[next] - time_[i];
  const double u = (t - time_[i]) / span;
  const Pose& a = pose_[i];
  const Pose& b = pose_[next];
  Sample out;
  out.pose.position = a.position + u * (b.position - a.position);
  out.pose.orientation = a.orientation.slerp(u, b.orientation).normalized();
  out.twist.linear = (b.position - a.position) / span;
  // slerp turns at the constant world-frame rate log(q_b conj(q_a)) / span, the short way.
  out.twist.angular = rotation_vector(b.orientation * a.orientation.conjugate()) / span;
  return out;
}

}  // namespace mssph
