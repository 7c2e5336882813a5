#include "talus/analysis/force_network_pdf.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace talus {
namespace {

// Fills counts and density on given edges; `locate` maps a ratio to its bin or -1.
template <class Locate>
void fill(ForcePdf& pdf, const std::vector<double>& ratios, Locate locate) {
  const std::size_t bins = pdf.edges.size() - 1;
  std::vector<double> counts(bins, 0.0);
  for (double r : ratios) {
    const long k = locate(r);
    if (k < 0) ++pdf.outside;
    else counts[static_cast<std::size_t>(k)] += 1;
  }
  pdf.density.resize(bins);
  for (std::size_t k = 0; k < bins; ++k) {
    const double width = pdf.edges[k + 1] - pdf.edges[k];
    pdf.density[k] = counts[k] / (static_cast<double>(ratios.size()) * width);
  }
}

std::vector<double> scaled(const std::vector<double>& forces, ForcePdf& pdf) {
  pdf.samples = forces.size();
  if (forces.empty()) throw std::invalid_argument("force pdf: no forces");
  pdf.mean_force = std::accumulate(forces.begin(), forces.end(), 0.0) / static_cast<double>(forces.size());
  if (!(pdf.mean_force > 0)) throw std::invalid_argument("force pdf: mean force is not positive");
  std::vector<double> ratios(forces.size());
  for (std::size_t k = 0; k < forces.size(); ++k) ratios[k] = forces[k] / pdf.mean_force;
  return ratios;
}

}  // namespace

ForcePdf force_pdf_linear(const std::vector<double>& forces, int bins, double max_ratio) {
  if (bins < 1) throw std::invalid_argument("force_pdf_linear: bins must be positive");
  ForcePdf pdf;
  const std::vector<double> ratios = scaled(forces, pdf);
  if (max_ratio <= 0) max_ratio = *std::max_element(ratios.begin(), ratios.end());
  const double width = max_ratio / bins;
  for (int k = 0; k <= bins; ++k) pdf.edges.push_back(k * width);
  for (int k = 0; k < bins; ++k) pdf.centres.push_back((k + 0.5) * width);
  fill(pdf, ratios, [&](double r) -> long {
    if (r < 0 || r > max_ratio) return -1;
    return std::min<long>(static_cast<long>(r / width), bins - 1);  // the largest lands in the last bin
  });
  return pdf;
}

ForcePdf force_pdf_log(const std::vector<double>& forces, int bins, double min_ratio, double max_ratio) {
  if (bins < 1) throw std::invalid_argument("force_pdf_log: bins must be positive");
  ForcePdf pdf;
  const std::vector<double> ratios = scaled(forces, pdf);
  if (min_ratio <= 0) {
    min_ratio = std::numeric_limits<double>::infinity();
    for (double r : ratios) {
      if (r > 0) min_ratio = std::min(min_ratio, r);
    }
  }
  if (max_ratio <= 0) max_ratio = *std::max_element(ratios.begin(), ratios.end());
  if (!(max_ratio > min_ratio)) max_ratio = min_ratio * 1.000001;  // all forces equal: one narrow range
  const double l0 = std::log(min_ratio), step = (std::log(max_ratio) - l0) / bins;
  for (int k = 0; k <= bins; ++k) pdf.edges.push_back(std::exp(l0 + k * step));
  pdf.edges.front() = min_ratio;
  pdf.edges.back() = max_ratio;
  for (int k = 0; k < bins; ++k) pdf.centres.push_back(std::sqrt(pdf.edges[k] * pdf.edges[k + 1]));
  fill(pdf, ratios, [&](double r) -> long {
    if (!(r >= min_ratio) || r > max_ratio) return -1;
    return std::clamp<long>(static_cast<long>((std::log(r) - l0) / step), 0, bins - 1);
  });
  return pdf;
}

}  // namespace talus
