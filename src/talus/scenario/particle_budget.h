#pragma once
// The particles a scenario asks for, added up while it is read, against a limit: a count that
// cannot be built is an InputError naming the key that passed the limit, before any memory or
// time is spent on it (a count of 1e12 would otherwise run the placement until the allocation
// fails).
#include <cstddef>
#include <string>

#include "talus/io/scenario_file.h"

namespace talus {

class ParticleBudget {
 public:
  ParticleBudget(const io::ScenarioFile& file, std::size_t limit) : file_(file), limit_(limit) {}
  // Adds `count` particles asked for by `key`; throws InputError once the total passes the
  // limit. A double, so that a count computed from lengths (the chute's) cannot overflow.
  void add(const std::string& key, double count);

 private:
  const io::ScenarioFile& file_;
  std::size_t limit_;
  double total_ = 0;
};

}  // namespace talus
