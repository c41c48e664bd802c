// The Interrupt of the long computations (capsubot/model/interrupt.hpp): each one asks it on the
// calling thread only, is abandoned with the very exception it throws (through NLopt too, and
// with nothing asked after the throw), and gives the same numbers when it never throws.

#include "capsubot/model/interrupt.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <nlopt.hpp>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/gait_from_rest.hpp"
#include "capsubot/attract/periodic.hpp"
#include "capsubot/design/design_from_rest.hpp"
#include "capsubot/optimize/detail/nlopt_status.hpp"
#include "capsubot/optimize/optimize_fourier.hpp"
#include "capsubot/optimize/optimize_phase.hpp"
#include "capsubot/orbit/validity.hpp"
#include "capsubot/reach/optimize_reach.hpp"
#include "design/example_robot.hpp"

namespace capsubot {
namespace {

// The exception a test's interrupt throws: nothing in the library throws it.
struct Abandon : std::exception {};

// An interrupt that counts its asks and whether each came from the thread that made it, and
// throws Abandon at ask number `throw_at` (0: never).
class CountingInterrupt {
 public:
  explicit CountingInterrupt(int throw_at) : throw_at_(throw_at) {}
  Interrupt Get() {
    return [this] {
      ++asks_;
      if (std::this_thread::get_id() != owner_) ++foreign_asks_;
      if (asks_ == throw_at_) throw Abandon();
    };
  }
  int asks() const { return asks_; }
  int foreign_asks() const { return foreign_asks_; }

 private:
  const std::thread::id owner_ = std::this_thread::get_id();
  const int throw_at_;
  int asks_ = 0;
  int foreign_asks_ = 0;
};

// The one-impact orbit of docs/model.md section 4 with T0 = 0.1, e = 0.5 (valid and stable).
const Forcing kSmallOrbitForce = Forcing::Harmonic(0.05, 0.02, -2.842);
Params SmallOrbitParams() {
  Params p;
  p.T0 = 0.1;
  p.e = 0.5;
  return p;
}

// A long computation with its options' interrupt(s) set to the given one.
struct LongCall {
  std::string name;
  std::function<void(const Interrupt&)> run;
};

PhaseState NearSmallOrbit() {
  const Orbit o = Solve(kSmallOrbitForce, SmallOrbitParams()).orbit;
  PhaseState z;  // right after the impact, 1 % off in u and v
  z.x = 1.0;
  z.u = -o.e * o.u * 1.01;
  z.v = o.v_plus * 0.99;
  z.psi = 0.0;
  return z;
}

std::vector<LongCall> LongCalls() {
  return {
      {"P1",
       [](const Interrupt& i) {
         PhaseOptions o;
         o.interrupt = i;
         OptimizePhase(Forcing::Harmonic(0.5, 0.5, 0.0), Params{}, o);
       }},
      {"P2_multistart",
       [](const Interrupt& i) {
         ForcingDesignOptions o;
         o.interrupt = i;
         OptimizeForcing(Params{}, o);
       }},
      // The first evaluations are inside NLopt's global stage: the throw crosses NLopt.
      {"P2_NLopt_global",
       [](const Interrupt& i) {
         ForcingDesignOptions o;
         o.effort.global_algorithm = "GN_ISRES";
         o.interrupt = i;
         OptimizeForcing(Params{}, o);
       }},
      {"P3",
       [](const Interrupt& i) {
         FourierOptions o;
         o.harmonic.interrupt = i;
         OptimizeFourier(Params{}, o);
       }},
      // Without a seed the first evaluations are the NLopt search's (MaximizeOnBox).
      {"reach",
       [](const Interrupt& i) {
         ReachOptions o;
         o.search.attractor.interrupt = o.check.attractor.interrupt = i;
         OptimizeReach(SmallOrbitParams(), OptimizeResult{}, o);
       }},
      {"periodic_transient",
       [](const Interrupt& i) {
         ShootingOptions o;
         o.transient = 1000;
         o.interrupt = i;
         FindPeriodicMotion({kSmallOrbitForce, SmallOrbitParams(), 0.3}, RestStart(0.5, 0.0), o);
       }},
      {"periodic_newton",
       [](const Interrupt& i) {
         const Orbit orbit = Solve(kSmallOrbitForce, SmallOrbitParams()).orbit;
         ShootingOptions o;
         o.interrupt = i;
         ShootPeriodicMotion({orbit.forcing, SmallOrbitParams(), orbit.alpha}, NearSmallOrbit(), 1,
                             o);
       }},
      {"gait_from_rest",
       [](const Interrupt& i) {
         FromRestOptions o;
         o.attractor.interrupt = i;
         CheckGaitFromRest(Solve(kSmallOrbitForce, SmallOrbitParams()).orbit, SmallOrbitParams(),
                           o);
       }},
      {"design_from_rest",
       [](const Interrupt& i) {
         DesignFromRestOptions o;
         o.search.attractor.interrupt = o.check.attractor.interrupt = i;
         DesignFromRest(testing::ExampleRobot(), o);
       }},
  };
}

class InterruptOf : public ::testing::TestWithParam<LongCall> {};

// Thrown at the third ask: the computations ask far more often, and the third ask of those
// whose first evaluations run inside NLopt comes from inside NLopt.
constexpr int kThrowAt = 3;

TEST_P(InterruptOf, AbandonsTheRunWithItsExceptionAskingNothingAfterIt) {
  CountingInterrupt interrupt(kThrowAt);
  EXPECT_THROW(GetParam().run(interrupt.Get()), Abandon);
  EXPECT_EQ(interrupt.asks(), kThrowAt);
  EXPECT_EQ(interrupt.foreign_asks(), 0) << "asked on a worker thread";
}

INSTANTIATE_TEST_SUITE_P(LongCalls, InterruptOf, ::testing::ValuesIn(LongCalls()),
                         [](const auto& info) { return info.param.name; });

TEST(Interrupt, ThatNeverThrowsIsAskedOnTheCallingThreadAndChangesNoNumber) {
  {
    ForcingDesignOptions o;
    o.effort.starts = 2;
    o.hops = 1;
    const OptimizeResult plain = OptimizeForcing(Params{}, o);
    CountingInterrupt interrupt(0);
    o.interrupt = interrupt.Get();
    const OptimizeResult asked = OptimizeForcing(Params{}, o);
    EXPECT_GT(interrupt.asks(), 0);
    EXPECT_EQ(interrupt.foreign_asks(), 0);
    EXPECT_EQ(asked.solution.orbit.I, plain.solution.orbit.I);
    EXPECT_EQ(asked.solution.orbit.forcing.phi0(), plain.solution.orbit.forcing.phi0());
    EXPECT_EQ(asked.evaluations, plain.evaluations);
  }
  {
    ShootingOptions o;
    o.transient = 200;
    const PeriodicMotion plain =
        FindPeriodicMotion({kSmallOrbitForce, SmallOrbitParams(), 0.3}, RestStart(0.5, 0.0), o);
    CountingInterrupt interrupt(0);
    o.interrupt = interrupt.Get();
    const PeriodicMotion asked =
        FindPeriodicMotion({kSmallOrbitForce, SmallOrbitParams(), 0.3}, RestStart(0.5, 0.0), o);
    EXPECT_GE(interrupt.asks(), o.transient);  // at least once a period of the transient
    EXPECT_EQ(interrupt.foreign_asks(), 0);
    EXPECT_EQ(asked.state.x, plain.state.x);
    EXPECT_EQ(asked.state.v, plain.state.v);
    EXPECT_EQ(asked.mean_velocity, plain.mean_velocity);
    EXPECT_EQ(asked.iterations, plain.iterations);
  }
  {
    FromRestOptions o;
    const Attractors plain = FindAttractors({kSmallOrbitForce, SmallOrbitParams(), 0.3}, o);
    CountingInterrupt interrupt(0);
    o.attractor.interrupt = interrupt.Get();
    const Attractors asked = FindAttractors({kSmallOrbitForce, SmallOrbitParams(), 0.3}, o);
    EXPECT_GT(interrupt.asks(), 0);
    EXPECT_EQ(interrupt.foreign_asks(), 0);
    EXPECT_EQ(asked.mean_velocity, plain.mean_velocity);
    EXPECT_EQ(asked.labels, plain.labels);
  }
}

// NLopt's C++ interface turns what an objective throws into its own failure; NloptCallbacks
// keeps it: the run stops at once (neither the objective nor the constraint is called again)
// and the caller gets the objective's exception.
struct Calls {
  int objective = 0, constraint = 0;
  int constraint_at_throw = -1;
};

double ThrowsAtTheFifthCall(unsigned, const double* x, double*, void* data) {
  auto* calls = static_cast<Calls*>(data);
  if (++calls->objective == 5) {
    calls->constraint_at_throw = calls->constraint;
    throw std::logic_error("the objective's own exception");
  }
  return -x[0] * x[0];
}

double AlwaysHolds(unsigned, const double*, double*, void* data) {
  ++static_cast<Calls*>(data)->constraint;
  return -1.0;
}

TEST(NloptCallbacks, StopTheRunAndRethrowWhatTheObjectiveThrew) {
  Calls calls;
  detail::NloptCallbacks callbacks;
  bool nlopt_stopped = false;
  try {
    nlopt::opt opt(nlopt::LN_COBYLA, 1);
    opt.set_lower_bounds({-1.0});
    opt.set_upper_bounds({1.0});
    opt.set_max_objective(detail::NloptCallbacks::Call,
                          callbacks.Wrap(ThrowsAtTheFifthCall, &calls));
    opt.add_inequality_constraint(detail::NloptCallbacks::Call, callbacks.Wrap(AlwaysHolds, &calls),
                                  0.0);
    opt.set_maxeval(100);
    std::vector<double> x = {0.7};
    double f = 0.0;
    opt.optimize(x, f);
  } catch (const nlopt::forced_stop&) {
    nlopt_stopped = true;
  }
  EXPECT_TRUE(nlopt_stopped);
  EXPECT_EQ(calls.objective, 5);
  EXPECT_EQ(calls.constraint, calls.constraint_at_throw);
  try {
    callbacks.Rethrow();
    ADD_FAILURE() << "Rethrow threw nothing";
  } catch (const std::logic_error& e) {
    EXPECT_STREQ(e.what(), "the objective's own exception");
  }
}

TEST(NloptCallbacks, RethrowNothingWhenNothingWasThrown) {
  detail::NloptCallbacks callbacks;
  EXPECT_NO_THROW(callbacks.Rethrow());
}

}  // namespace
}  // namespace capsubot
