// Time built-ins. Both read and advance the run's clock through the host, so a headless run is
// deterministic and never sleeps.
#include "machine/builtins_impl.h"
#include "base/runtime_error.h"

namespace rb::builtins {

Value timeTimer(Machine& m, Args&) {
  return Value::integer(static_cast<int64_t>(m.host().clockMs()));
}

Value timeDelay(Machine& m, Args& a) {
  // A day at most: longer waits are a mistake (the --timeout limit would stop them anyway), and
  // the clock stays a whole number of milliseconds that fits any integer.
  double ms = a.within(0, 86400e3);
  if (ms > 0) m.delay(ms);
  return {};
}

}  // namespace rb::builtins
