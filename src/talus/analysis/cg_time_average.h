#pragma once
// Time averaging of coarse-grained fields over a window of snapshots (Weinhart et al. 2012,
// Eq. 43, with snapshots equally spaced in time so the time integral is their mean).
#include <utility>

#include "talus/analysis/cg_fields.h"

namespace talus {

class CgTimeAverage {
 public:
  // Adds one snapshot's fields; all must be on the same grid (throws otherwise).
  void add(const CgFields& fields);
  int count() const { return count_; }
  // The mean fields. Every stored field is averaged linearly, so velocity() of the result is
  // <p>/<rho>, and kinetic_stress is the mean of the instantaneous sum m v'v' W (the paper's
  // Eq. 43 applied to Eq. 32). The mean momentum_flux also carries the temporal velocity
  // fluctuations (Reynolds stress), which is why the balance checks use it.
  CgFields mean() const;
  // The running sum, and the inverse: restart an average from a saved sum (checkpoints).
  const CgFields& sum() const { return sum_; }
  static CgTimeAverage from_sum(CgFields sum, int count) {
    CgTimeAverage a;
    a.sum_ = std::move(sum);
    a.count_ = count;
    return a;
  }

 private:
  CgFields sum_;
  int count_ = 0;
};

}  // namespace talus
