// libFuzzer target for the scenario reader: the input bytes are a scenario file, read and built
// into a World as `talus check` does (no steps are run). The only clean outcomes are a World or
// an io::InputError in the `FILE:LINE: KEY: message` form; anything else - another exception,
// a crash, a sanitizer report, a hang - is a bug, and aborts so that libFuzzer keeps the input.
// Run it with scripts/fuzz.sh.
#include <omp.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "talus/io/input_error.h"
#include "talus/scenario/scenario.h"

namespace {

constexpr std::string_view kName = "fuzz.toml";

// A scenario may rightly ask for a million particles; building them costs time, not
// correctness. Above this many the reader refuses the input with an InputError naming the
// count, through the same check that refuses absurd counts for users (ScenarioLimits). It
// also keeps out the chute's rough base (at least 73 spheres), which is settled by a
// simulation of thousands of steps: running steps is not what this target tests.
constexpr std::size_t kMaxParticles = 50;

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  // One thread: an input then replays the same way, and no team is started per input.
  omp_set_num_threads(1);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    talus::io::ScenarioFile file = talus::io::ScenarioFile::from_string(text, std::string(kName));
    talus::ScenarioLimits limits;
    limits.max_particles = kMaxParticles;
    const talus::Scenario scenario = talus::load_scenario(file, limits);
    (void)file.to_toml();  // `talus check` writes this into the checkpoint estimate
  } catch (const talus::io::InputError& e) {
    static const bool verbose = std::getenv("TALUS_FUZZ_VERBOSE") != nullptr;  // to see why a replayed input fails
    if (verbose) std::fprintf(stderr, "%s\n", e.what());
    // Every problem must say where it is: the file name, then a line or the key.
    for (const auto& message : e.messages())
      if (!message.starts_with(kName) || message.size() == kName.size() || message[kName.size()] != ':') {
        std::fprintf(stderr, "InputError without the file name: %s\n", message.c_str());
        std::abort();
      }
  }
  return 0;
}
