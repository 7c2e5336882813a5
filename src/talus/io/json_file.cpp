#include "talus/io/json_file.h"

#include "talus/io/atomic_file.h"

namespace talus::io {

void write_json(const std::filesystem::path& path, const nlohmann::json& value, int indent) {
  std::string text = value.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
  text += '\n';
  atomic_write(path, text);
}

}  // namespace talus::io
