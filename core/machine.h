#pragma once
// The state a running program changes besides its variables: the host it talks to, the random
// generator, and (as the simulator grows) the screen and the robot. Built-in handlers receive
// the Machine; the interpreter owns none of this.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "host.h"
#include "rng.h"

namespace rb {

class Machine {
 public:
  Machine(Host& host, uint64_t seed) : host_(host), rng_(seed), seed_(seed) {}
  Machine(const Machine&) = delete;
  Machine& operator=(const Machine&) = delete;

  Host& host() { return host_; }
  /// The random generator; using it marks the run as depending on the seed.
  Rng& rng() {
    rngUsed_ = true;
    return rng_;
  }
  bool rngUsed() const { return rngUsed_; }
  uint64_t seed() const { return seed_; }

  /// `print`: writes the text, then a line end unless `newline` is false.
  void print(std::string_view text, bool newline);
  /// `input`: shows the prompt and reads a line; a RuntimeError when input is over.
  std::string input(std::string_view prompt);
  /// `delay`: lets time pass on the run's clock.
  void delay(double ms);

 private:
  Host& host_;
  Rng rng_;
  uint64_t seed_;
  bool rngUsed_ = false;
};

}  // namespace rb
