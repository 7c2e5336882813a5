#pragma once
// Resident memory of this process, from /proc/self/status (Linux).
#include <cstddef>

namespace talus::bench {

std::size_t resident_kib();       ///< VmRSS, KiB; 0 if unavailable
std::size_t peak_resident_kib();  ///< VmHWM (high-water mark of VmRSS), KiB; 0 if unavailable
// Lowers VmHWM to the current VmRSS (writes 5 to /proc/self/clear_refs); false if not allowed.
bool reset_peak_resident();

}  // namespace talus::bench
