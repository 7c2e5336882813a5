#pragma once
// Vec3 and Quat arrays as rows of doubles and back: how HDF5 files store them (n x 3, n x 4).
#include <vector>

#include "talus/math/quat.h"
#include "talus/math/vec3.h"

namespace talus::io {

inline std::vector<double> flat(const std::vector<Vec3>& v) {
  std::vector<double> out;
  out.reserve(3 * v.size());
  for (const Vec3& x : v) out.insert(out.end(), {x.x, x.y, x.z});
  return out;
}

inline std::vector<Vec3> vec3s(const std::vector<double>& v) {
  std::vector<Vec3> out(v.size() / 3);
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = {v[3 * k], v[3 * k + 1], v[3 * k + 2]};
  return out;
}

inline std::vector<double> flat(const std::vector<Quat>& v) {
  std::vector<double> out;
  out.reserve(4 * v.size());
  for (const Quat& q : v) out.insert(out.end(), {q.w, q.x, q.y, q.z});
  return out;
}

inline std::vector<Quat> quats(const std::vector<double>& v) {
  std::vector<Quat> out(v.size() / 4);
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = {v[4 * k], v[4 * k + 1], v[4 * k + 2], v[4 * k + 3]};
  return out;
}

}  // namespace talus::io
