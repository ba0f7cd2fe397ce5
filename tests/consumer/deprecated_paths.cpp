// The include paths of hinf_cpp 0.1 still build against the installed 0.2 package: every
// forwarding header (cpp/deprecated/hinf) is included here, and a type from each layer is named,
// so that a program written for 0.1 compiles unchanged (with a note per header). main.cpp uses
// the layer folders of 0.2.
#define HINF_NO_DEPRECATED_HEADER_MESSAGES
#include <hinf/analysis.hpp>
#include <hinf/angles.hpp>
#include <hinf/checks.hpp>
#include <hinf/controller.hpp>
#include <hinf/cvode.hpp>
#include <hinf/dense_piece.hpp>
#include <hinf/disturbance.hpp>
#include <hinf/dopri5.hpp>
#include <hinf/enum_names.hpp>
#include <hinf/errors.hpp>
#include <hinf/fleet.hpp>
#include <hinf/generated_function.hpp>
#include <hinf/generated_model.hpp>
#include <hinf/metrics.hpp>
#include <hinf/model.hpp>
#include <hinf/output_feedback.hpp>
#include <hinf/piecewise_polynomial.hpp>
#include <hinf/resources.hpp>
#include <hinf/riccati.hpp>
#include <hinf/scenario.hpp>
#include <hinf/scenario_io.hpp>
#include <hinf/sdirk4.hpp>
#include <hinf/ship.hpp>
#include <hinf/signal.hpp>
#include <hinf/simulation.hpp>
#include <hinf/solver_options.hpp>
#include <hinf/sparse_matrix.hpp>
#include <hinf/stepper.hpp>
#include <hinf/study.hpp>
#include <hinf/trajectory.hpp>
#include <hinf/types.hpp>
#include <hinf/vehicles.hpp>

// Called by main(): the ship of 0.1's hinf/ship.hpp (which also declared the cascade law) and a
// scenario written by 0.1's hinf/scenario_io.hpp.
int deprecated_paths_work() {
  const hinf::ShipModel ship;
  const hinf::CascadeGains gains;
  hinf::Scenario scenario;
  scenario.model = std::make_shared<const hinf::Auv>();
  (void)scenario;
  return ship.n() == 6 && gains.k > 0.0 && hinf::model_kind_names().size() >= 8 ? 0 : 1;
}
