#pragma once
// A load that grows without bound: the divergence check of the rigid bodies' loads. A
// numerical instability of the flow around a penalized body (for example PISO's at a large
// viscous number, docs/verification.md) multiplies the body's force or torque by a nearly
// constant factor every step, long before any velocity reaches the fluid's speed limit: the
// torque may stay right while the force, which symmetry makes zero, grows from 1e-4 N to 30 N.
// Physical loads do not: an impact or the onset of vortex shedding grows fast over a few steps
// only, and a load growing from rest like t^p grows by 10 % per step up to step 10 p, ever
// more slowly. The check: a load that grew by at least kGrowthPerStep at each of the last
// kSteps steps (17 times over 30 steps), and as fast over the last third of them as over the
// first (three quarters of its logarithmic rate at least: t^6 from rest slows by half), runs
// away.

#include "fluid_adapter/rigid/BodyLoads.hpp"

#include <deque>
#include <string>
#include <vector>

namespace fsi::fluid::rigid {

class RunawayLoadCheck {
public:
  static constexpr int kSteps = 30;
  static constexpr double kGrowthPerStep = 1.1;

  /// Records the loads of the bodies (in the order of names) at the end of the step `step`,
  /// ending at time_s. A step taken again (implicit coupling: the same time_s) replaces its
  /// first record. Returns "" or the message naming the body, the load, its growth and the step.
  std::string observe(long step, double time_s, const std::vector<std::string> &names,
                      const std::vector<BodyLoad> &loads);

private:
  /// The last kSteps + 1 magnitudes (|F| or |T|) of one body, oldest first.
  using Window = std::deque<double>;
  struct Record {
    bool recorded = false;
    double time_s = 0.0;
    Window force, torque;
  };

  static void push(Window &window, double value, bool replace_last);
  static bool runs_away(const Window &window);
  static std::string describe(const std::string &body, const char *what, const char *unit, const Window &window,
                              long step, double time_s);

  std::vector<Record> records_;
};

} // namespace fsi::fluid::rigid
