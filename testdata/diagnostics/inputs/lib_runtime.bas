// nontest: included by include_runtime.bas
sub Half(n)
  return n / d
