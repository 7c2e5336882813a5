#pragma once
// A part of a scenario that watches, and may steer, a run: the dam break's phases (pour, settle,
// open the gate, collapse), the chute's coarse graining. The run loop calls every observer at
// fixed points of the run; observers write their own files into the results folder, atomically.
#include <filesystem>
#include <limits>
#include <string>

#include <nlohmann/json.hpp>

#include "talus/world/world.h"

namespace talus {

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual std::string name() const = 0;
  // Before the first step; `out` is the results folder.
  virtual void start(World& /*world*/, const std::filesystem::path& /*out*/) {}
  // After every step: keep it cheap. May move walls or remove particles. The run loop steps in
  // batches (World::run) and calls it at the end of each batch only; a batch never runs past
  // the first step that reaches next_step_event().
  virtual void after_step(World& /*world*/) {}
  // Time from which after_step has something to do (-infinity: at every step).
  virtual double next_step_event(const World& /*world*/) const { return std::numeric_limits<double>::infinity(); }
  // At every output step with its diagnostics; returning true ends the run with stop_reason().
  virtual bool output(World& /*world*/, const Diagnostics& /*d*/) { return false; }
  virtual std::string stop_reason() const { return name(); }
  // After the last step: adds its figures to summary.json and writes its own files into `out`.
  virtual void finish(World& /*world*/, const std::filesystem::path& /*out*/, nlohmann::json& /*summary*/) {}
  // `talus analyze DIR`: measures again from the files a finished run left in `dir` (for example
  // with other thresholds set on the command line); returns false when it has nothing to redo.
  virtual bool reanalyse(const std::filesystem::path& /*dir*/, nlohmann::json& /*summary*/) { return false; }
  // What a checkpoint must carry to resume the observer exactly where it was. A restarted run
  // calls start() on the scenario's fresh World, then puts the World back into the
  // checkpoint's state (walls, gravity and contact model included), then calls restore().
  virtual nlohmann::json state() const { return nlohmann::json::object(); }
  virtual void restore(const nlohmann::json& /*state*/) {}
};

}  // namespace talus
