#include "talus/io/json_file.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "talus/io/atomic_file.h"

namespace talus::io {

void write_json(const std::filesystem::path& path, const nlohmann::json& value, int indent) {
  std::string text = value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
  text += '\n';
  atomic_write(path, text);
}

nlohmann::json non_finite_as_text(nlohmann::json value) {
  if (value.is_structured()) {
    for (auto& item : value) item = non_finite_as_text(std::move(item));
    return value;
  }
  if (!value.is_number_float()) return value;
  const double v = value.get<double>();
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return value;
}

nlohmann::json read_json(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path.string() + ": cannot open");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": not valid JSON (" + e.what() + ")");
  }
}

}  // namespace talus::io
