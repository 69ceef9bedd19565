#pragma once
// Type-erased configuration of one coupling law (the keys of the case's `coupling` section
// that belong to the chosen law). Each law declares its keys in `visit_keys(V&)` and derives
// from CouplingLawConfigBase<Self>, which forwards the three configuration visitors.

#include "CouplingLaw.hpp"
#include "common/ConfigDocWriter.hpp"
#include "common/ConfigEmitter.hpp"
#include "common/ConfigReader.hpp"

#include <memory>

namespace fsi::coupler {

class CouplingLawConfig {
public:
  virtual ~CouplingLawConfig() = default;
  virtual void visit(common::ConfigReader &v) = 0;
  virtual void visit(common::ConfigEmitter &v) = 0;
  virtual void visit(common::ConfigDocWriter &v) = 0;
  virtual std::unique_ptr<CouplingLaw> build() const = 0;
  /// Largest time step (s) for which the law is stable on a structure of areal (or linear)
  /// density rho_1 (kg/m^2 or kg/m); infinity when the law sets no limit.
  virtual double stable_time_step_s(double mass_per_measure) const = 0;
};

template <class Derived> class CouplingLawConfigBase : public CouplingLawConfig {
public:
  void visit(common::ConfigReader &v) override { self().visit_keys(v); }
  void visit(common::ConfigEmitter &v) override { self().visit_keys(v); }
  void visit(common::ConfigDocWriter &v) override { self().visit_keys(v); }

private:
  Derived &self() { return static_cast<Derived &>(*this); }
};

} // namespace fsi::coupler
