#include "talus/io/input_file.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "talus/io/input_error.h"

namespace talus::io {

std::string read_input_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path.string() + ": cannot open: is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open: " + std::strerror(errno));
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (in.bad()) throw InputError(path.string() + ": cannot read: " + std::strerror(errno));
  return std::move(bytes).str();
}

}  // namespace talus::io
