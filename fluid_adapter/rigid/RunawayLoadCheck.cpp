#include "fluid_adapter/rigid/RunawayLoadCheck.hpp"

#include <cmath>
#include <sstream>

namespace fsi::fluid::rigid {

std::string RunawayLoadCheck::observe(long step, double time_s, const std::vector<std::string> &names,
                                      const std::vector<BodyLoad> &loads) {
  if (records_.size() != loads.size())
    records_.assign(loads.size(), Record{});
  for (std::size_t b = 0; b < loads.size(); ++b) {
    Record &r = records_[b];
    const bool again = r.recorded && r.time_s == time_s;
    push(r.force, loads[b].force_n.norm(), again);
    push(r.torque, loads[b].torque_n_m.norm(), again);
    r.recorded = true;
    r.time_s = time_s;
    const std::string &name = b < names.size() ? names[b] : std::to_string(b);
    if (runs_away(r.force))
      return describe(name, "force", "N", r.force, step, time_s);
    if (runs_away(r.torque))
      return describe(name, "torque", "N m", r.torque, step, time_s);
  }
  return "";
}

void RunawayLoadCheck::push(Window &window, double value, bool replace_last) {
  if (replace_last && !window.empty())
    window.pop_back();
  window.push_back(value);
  if (window.size() > static_cast<std::size_t>(kSteps) + 1)
    window.pop_front();
}

bool RunawayLoadCheck::runs_away(const Window &window) {
  if (window.size() < static_cast<std::size_t>(kSteps) + 1 || !(window.front() > 0.0))
    return false;
  for (std::size_t k = 1; k < window.size(); ++k)
    if (!(window[k] >= kGrowthPerStep * window[k - 1]))
      return false;
  const std::size_t third = kSteps / 3;
  const double first = std::log(window[third] / window[0]);
  const double last = std::log(window[kSteps] / window[kSteps - third]);
  return last >= 0.75 * first;
}

std::string RunawayLoadCheck::describe(const std::string &body, const char *what, const char *unit,
                                       const Window &window, long step, double time_s) {
  std::ostringstream text;
  text << "the fluid diverged at step " << step << " (t = " << time_s << " s): the " << what << " on rigid body '"
       << body << "' grows without bound: it grew by at least " << std::lround((kGrowthPerStep - 1.0) * 100.0)
       << " % at each of the last " << kSteps << " steps, from " << window.front() << " " << unit << " to "
       << window.back() << " " << unit
       << ". A numerical instability, not physics. Likely cause: a time step too large for the viscous number "
          "(nu dt sum 1/dx^2, logged at the start) with these PIMPLE settings (docs/verification.md, the limits of "
          "PISO), or for a thin penalized solid with fluid on both sides: reduce run.time_step_s";
  return text.str();
}

} // namespace fsi::fluid::rigid
