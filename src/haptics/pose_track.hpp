#pragma once
// A pose path through timed poses: positions interpolated linearly, orientations by slerp (the
// short way), held at the first pose before it and at the last after it. Scripted keyframes and
// recorded device trajectories are both read through it, at the haptic rate.
#include "util/pose.hpp"

#include <vector>

namespace mssph {

class PoseTrack {
 public:
  // `time` strictly increasing, as long as `pose` and not empty (checked by the config reader).
  PoseTrack(std::vector<double> time, std::vector<Pose> pose);

  struct Sample {
    Pose pose;
    Twist twist;  // the interpolant's derivative on the segment holding t; zero outside the track
  };
  Sample at(double t) const;

 private:
  std::vector<double> time_;
  std::vector<Pose> pose_;
};

}  // namespace mssph
