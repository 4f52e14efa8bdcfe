// Time built-ins. Both read and advance the run's clock through the host, so a headless run is
// deterministic and never sleeps.
#include "machine/builtins_impl.h"
#include "base/runtime_error.h"

namespace rb::builtins {

Value timeTimer(Machine& m, Args&) {
  return Value::integer(static_cast<int64_t>(m.host().clockMs()));
}

Value timeDelay(Machine& m, Args& a) {
  double ms = a.num(0);
  if (ms > 0) m.delay(ms);
  return {};
}

}  // namespace rb::builtins
