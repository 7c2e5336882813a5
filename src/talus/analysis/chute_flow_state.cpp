#include "talus/analysis/chute_flow_state.h"

#include <cmath>
#include <stdexcept>

namespace talus {

std::string to_string(FlowState s) {
  switch (s) {
    case FlowState::arrested: return "arrested";
    case FlowState::steady: return "steady";
    case FlowState::accelerating: return "accelerating";
    case FlowState::decelerating: return "decelerating";
    case FlowState::layered: return "layered";
    case FlowState::oscillating: return "oscillating";
    case FlowState::undetermined: return "undetermined";
  }
  return "undetermined";
}

FlowState flow_state_from_string(const std::string& text) {
  for (FlowState s : {FlowState::arrested, FlowState::steady, FlowState::accelerating, FlowState::decelerating,
                      FlowState::layered, FlowState::oscillating, FlowState::undetermined})
    if (to_string(s) == text) return s;
  throw std::invalid_argument("unknown flow state \"" + text + "\"");
}

std::optional<double> arrest_time(const std::vector<EnergySample>& samples, const FlowStateCriteria& c) {
  for (const EnergySample& s : samples)
    if (s.elastic > 0 && s.kinetic < c.arrest_ratio * s.elastic) return s.time;
  return std::nullopt;
}

FlowStateResult classify_flow(const std::vector<EnergySample>& samples, const FlowStateCriteria& c) {
  FlowStateResult r;
  r.arrest_time = arrest_time(samples, c);
  if (samples.empty()) return r;
  const double t_end = samples.back().time;
  r.window_end = t_end;
  r.window_start = t_end - std::max(c.min_window, c.window_fraction * (t_end - samples.front().time));
  if (r.arrest_time && *r.arrest_time <= c.arrest_time) {
    r.state = FlowState::arrested;
    return r;
  }
  // <E_ela> over the window (Fig. 3 normalises by the mean elastic energy).
  std::vector<double> t, q;
  double elastic = 0;
  for (const EnergySample& s : samples)
    if (s.time >= r.window_start) {
      t.push_back(s.time);
      q.push_back(s.kinetic);
      elastic += s.elastic;
    }
  const std::size_t n = t.size();
  if (n < 5 || elastic <= 0) return r;
  elastic /= n;
  double tm = 0, qm = 0;
  for (std::size_t k = 0; k < n; ++k) {
    q[k] /= elastic;
    tm += t[k] / n;
    qm += q[k] / n;
  }
  double stt = 0, stq = 0;
  for (std::size_t k = 0; k < n; ++k) {
    stt += (t[k] - tm) * (t[k] - tm);
    stq += (t[k] - tm) * (q[k] - qm);
  }
  const double slope = stt > 0 ? stq / stt : 0;
  double rss = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double e = q[k] - (qm + slope * (t[k] - tm));
    rss += e * e;
  }
  r.mean_ratio = qm;
  r.relative_drift = qm > 0 ? slope * (t.back() - t.front()) / qm : 0;
  r.relative_rms = qm > 0 ? std::sqrt(rss / n) / qm : 0;
  if (r.arrest_time && samples.back().kinetic < c.arrest_ratio * elastic)
    r.state = FlowState::arrested;  // stopped after the arrest time limit
  else if (r.relative_rms > c.oscillation_tolerance)
    r.state = FlowState::oscillating;
  else if (r.relative_drift > c.drift_tolerance)
    r.state = FlowState::accelerating;
  else if (r.relative_drift < -c.drift_tolerance)
    r.state = FlowState::decelerating;
  else
    r.state = FlowState::steady;
  return r;
}

FlowState refine_with_layering(FlowState s, double layering, const FlowStateCriteria& c) {
  return s == FlowState::steady && layering > c.layering_tolerance ? FlowState::layered : s;
}

}  // namespace talus
