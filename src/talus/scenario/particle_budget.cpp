#include "talus/scenario/particle_budget.h"

#include <cmath>

#include "talus/io/number_format.h"

namespace talus {

void ParticleBudget::add(const std::string& key, double count) {
  total_ += count;
  // Also refuses NaN, which a computed count can be.
  if (total_ <= static_cast<double>(limit_)) return;
  const std::string total = total_ < 1e18 ? io::format_int(static_cast<std::int64_t>(std::llround(total_)))
                                           : io::format_double(total_);
  file_.fail(key, total + " particles in all, above the limit of " +
                      io::format_int(static_cast<std::int64_t>(limit_)));
}

}  // namespace talus
