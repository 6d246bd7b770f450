#include "haptics/proxy_predictor.hpp"

#include "backend/backend.hpp"

namespace mssph {

ProxyState proxy_state_of(const BodyState& state, double time) {
  ProxyState out;
  out.time = time;
  out.pose = Pose{state.centre_of_mass, state.orientation};
  out.twist = Twist{state.linear_momentum / state.mass, state.angular_velocity};
  out.interaction = Wrench{state.interaction_force, state.interaction_torque};
  return out;
}

// Semi-implicit Euler over the gap, the integrator of the simulation's rigid bodies:
//   v += (F_interaction + F_coupling) / m dt + g dt,  x += v dt,
//   L += (tau_interaction + tau_coupling) dt,  w = I_world^-1 L,  q = exp(w dt) q.
const ProxyState& ProxyPredictor::at(double t, const Wrench& coupling) {
  const double gap = t - state_.time;
  if (mode_ == BetweenSteps::hold || gap <= 0.0) return state_;
  const Eigen::Matrix3d r = state_.pose.orientation.toRotationMatrix();
  const Eigen::Matrix3d inertia = r * model_.inertia_body * r.transpose();
  state_.twist.linear += ((state_.interaction.force + coupling.force) / model_.mass + model_.gravity) * gap;
  state_.pose.position += state_.twist.linear * gap;
  const Eigen::Vector3d momentum = inertia * state_.twist.angular + (state_.interaction.torque + coupling.torque) * gap;
  state_.twist.angular = inertia.ldlt().solve(momentum);
  state_.pose.orientation = rotated(state_.pose.orientation, state_.twist.angular * gap);
  state_.time = t;
  return state_;
}

}  // namespace mssph
