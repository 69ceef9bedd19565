#pragma once
// The paper's explicit step (section 2.3): U_ib^n interpolated at X_ib^n, the coupling law of
// Eq. (5) gives F_fsi^n and X_ib^{n+1}, then the fluid (Eq. 8 and PIMPLE) and the structure
// (Eq. 4 and Eq. 11) advance concurrently under it.

#include "StepScheme.hpp"

namespace fsi::coupler {

class ExplicitStep final : public StepScheme {
public:
  void advance(long n, StepExchange &exchange) override;
};

} // namespace fsi::coupler
