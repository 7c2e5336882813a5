#pragma once
// The machine's 1-minute load average (/proc/loadavg): other jobs inflate the timings, the
// 2-thread ones most, so each case prints it next to its figures.
namespace talus::bench {

double load_average();  ///< 0 if unavailable

}  // namespace talus::bench
