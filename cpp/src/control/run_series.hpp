// What the closed loops (simulation.cpp, sampled_loop.cpp) record alike (private to the library).
#pragma once

#include <vector>

#include "hinf/control/disturbance.hpp"
#include "hinf/control/simulation.hpp"
#include "hinf/control/trajectory.hpp"

namespace hinf {

namespace detail {
// simulate_state_feedback (simulation.hpp) with the divergence bound given instead of computed from
// the run's own horizon (the receding horizon's pieces share the mission's bound).
SimulationResult simulate_state_feedback(const Trajectory& trajectory, Controller& controller,
                                         const Disturbance& disturbance, const Vec& q0,
                                         const SimulationOptions& options, const Model* plant, double bound);
}  // namespace detail

// The output grid of a closed loop over the trajectory's horizon (output_grid), after checking
// that the run's series (t, q, q_d, u, u_d and w of nw channels) fit in memory.
std::vector<double> run_grid(const Trajectory& trajectory, double output_dt, int nw);

// The series of a run that do not depend on the law, on the first `recorded` times of `grid`:
// t, q_d, u_d and w (the disturbance at the recorded states); result.q is cut to those rows and
// must hold them.
void record_reference_series(const Trajectory& trajectory, const Disturbance& disturbance,
                             const std::vector<double>& grid, long recorded, SimulationResult& result);

// The divergence test of a closed loop (simulation.hpp): the tracking error |q - q_d|_inf
// (heading wrapped) at the end of each step against the bound.
class DivergenceCheck {
 public:
  DivergenceCheck(const Trajectory& trajectory, int heading, double bound);
  // True while the state y at t is within the bound; else false, with the run marked Diverged and
  // a message that ends with `advice` (what the user can change).
  bool within(double t, const double* y, const char* advice, SimulationResult& result);

 private:
  const Trajectory& trajectory_;
  int heading_;
  double bound_;
  Vec q_d_, q_e_;
  std::size_t cursor_ = 0;
};

}  // namespace hinf
