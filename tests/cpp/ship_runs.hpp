// Ship trajectories and tight closed-loop settings shared by the tests of the ship's baseline
// laws (test_cascade.cpp, test_backstepping.cpp).
#pragma once

#include <memory>
#include <vector>

#include "hinf/control/simulation.hpp"
#include "hinf/control/trajectory.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/numerics/signal.hpp"

namespace hinf_test {

// The ship's desired trajectory from q_d0 under u_d on [0, tf].
inline hinf::TrajectoryPtr ship_trajectory(const hinf::ShipParameters& p, const hinf::Vec& q_d0,
                                           const hinf::VectorSignal& u_d, double tf) {
  return std::make_shared<const hinf::Trajectory>(std::make_shared<const hinf::ShipModel>(p), q_d0, u_d, 0.0, tf);
}

// Constant inputs (u1, u2).
inline hinf::VectorSignal constant_inputs(double u1, double u2) {
  return hinf::VectorSignal(std::vector<hinf::Signal>{hinf::Signal(u1), hinf::Signal(u2)});
}

// The paper's inputs: u1 = 1, u2 = 0.3 sin(0.2 t).
inline hinf::VectorSignal paper_u_d() {
  return hinf::VectorSignal(std::vector<hinf::Signal>{
      hinf::Signal(1.0), hinf::Signal(0.0, {hinf::Harmonic{0.3, 0.2, 0.0, false}})});
}

// The ship's state [u, v, r, x, y, psi].
inline hinf::Vec state(double u, double v, double r, double x, double y, double psi) {
  hinf::Vec q(6);
  q << u, v, r, x, y, psi;
  return q;
}

// Dormand-Prince at rtol 1e-11, atol 1e-13, output every output_dt.
inline hinf::SimulationOptions tight(double output_dt) {
  hinf::SimulationOptions o;
  o.output_dt = output_dt;
  o.solver.method = hinf::Method::ERK;
  o.solver.rtol = 1e-11;
  o.solver.atol = 1e-13;
  return o;
}

}  // namespace hinf_test
