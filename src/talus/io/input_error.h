#pragma once
// The one exception type for bad user input (scenario files, --set overrides, output folders).
// what() is exactly the GNU-style text `FILE:LINE: KEY: message`, one line per problem, so
// editors and CI logs can jump to the spot; nothing else is added to it.
#include <stdexcept>
#include <string>
#include <vector>

namespace talus::io {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : InputError(std::vector<std::string>{message}) {}
  explicit InputError(std::vector<std::string> messages)
      : std::runtime_error(join(messages)), messages_(std::move(messages)) {}

  // Each problem on its own, in the order they are reported in what().
  const std::vector<std::string>& messages() const { return messages_; }

 private:
  static std::string join(const std::vector<std::string>& lines) {
    std::string out;
    for (const auto& line : lines) {
      if (!out.empty()) out += '\n';
      out += line;
    }
    return out;
  }

  std::vector<std::string> messages_;
};

}  // namespace talus::io
