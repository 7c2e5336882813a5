// STL meshes, ASCII and binary (triangle_mesh_file.h).
#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include "talus/io/input_error.h"
#include "talus/io/mesh_text.h"
#include "talus/io/triangle_mesh_file.h"

namespace talus::io {

namespace {

std::uint32_t little_endian_u32(std::string_view bytes, std::size_t at) {
  std::uint32_t u = 0;
  for (int k = 3; k >= 0; --k) u = (u << 8) | static_cast<unsigned char>(bytes[at + k]);
  return u;
}

TriangleMesh parse_binary(std::string_view bytes, std::uint32_t count, const std::string& name) {
  TriangleMesh mesh;
  for (std::uint32_t facet = 0; facet < count; ++facet) {
    const std::size_t record = 84 + 50 * std::size_t{facet};
    std::array<int, 3> triangle{};
    for (int corner = 0; corner < 3; ++corner) {
      Vec3 p;
      for (int k = 0; k < 3; ++k) {
        // Past the facet's normal, 12 bytes.
        p[k] = std::bit_cast<float>(little_endian_u32(bytes, record + 12 + 12 * corner + 4 * k));
        if (!std::isfinite(p[k]))
          throw InputError(name + ": facet " + std::to_string(facet + 1) + ": a coordinate is not a finite number");
      }
      triangle[corner] = static_cast<int>(mesh.vertices.size());
      mesh.vertices.push_back(p);
    }
    mesh.triangles.push_back(triangle);
  }
  return mesh;
}

bool is_keyword(std::string_view word, std::string_view keyword) {
  return std::equal(word.begin(), word.end(), keyword.begin(), keyword.end(),
                    [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

std::string shown(std::string_view word) {
  if (word.empty()) return "the end of the file";
  std::string quoted = "'";
  quoted.append(word.substr(0, 40));
  return quoted + "'";
}

// Whitespace-separated words with the line each is on.
class Words {
 public:
  Words(std::string_view text, const std::string& name) : text_(text), name_(name) {}

  bool at_end() {
    skip_space();
    return pos_ == text_.size();
  }
  std::string_view next() {
    skip_space();
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    if (pos_ > start) word_line_ = line_;  // at the end, messages point at the last word
    return text_.substr(start, pos_ - start);
  }
  // The next word, which must be `keyword` (in any case, as some exporters write "FACET NORMAL").
  void expect(std::string_view keyword) {
    const std::string_view word = next();
    if (!is_keyword(word, keyword)) fail("expected `" + std::string(keyword) + "`, got " + shown(word));
  }
  double number() {
    const std::string_view word = next();
    const std::optional<double> value = finite_number(word);
    if (!value) fail("expected a finite number, got " + shown(word));
    return *value;
  }
  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(name_ + ":" + std::to_string(word_line_) + ": " + message);
  }

 private:
  void skip_space() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }

  std::string_view text_;
  const std::string& name_;
  std::size_t pos_ = 0;
  int line_ = 1;       ///< where pos_ is
  int word_line_ = 1;  ///< of the word last read
};

// One or more `solid NAME ... endsolid NAME` blocks.
TriangleMesh parse_ascii(std::string_view text, const std::string& name) {
  TriangleMesh mesh;
  Words words(text, name);
  do {
    words.expect("solid");
    words.skip_line();  // the name, which may hold spaces
    while (true) {
      const std::string_view word = words.next();
      if (is_keyword(word, "endsolid")) break;
      if (!is_keyword(word, "facet"))
        words.fail("expected `facet` or `endsolid`, got " + shown(word));
      words.expect("normal");
      for (int k = 0; k < 3; ++k) words.number();  // the corner order orients the facet, not this
      words.expect("outer");
      words.expect("loop");
      std::array<int, 3> triangle{};
      for (int corner = 0; corner < 3; ++corner) {
        words.expect("vertex");
        const double x = words.number(), y = words.number(), z = words.number();
        triangle[corner] = static_cast<int>(mesh.vertices.size());
        mesh.vertices.push_back({x, y, z});
      }
      words.expect("endloop");
      words.expect("endfacet");
      mesh.triangles.push_back(triangle);
    }
    words.skip_line();
  } while (!words.at_end());
  return mesh;
}

}  // namespace

TriangleMesh parse_stl_mesh(std::string_view bytes, const std::string& name) {
  if (bytes.size() >= 84) {
    const std::uint32_t count = little_endian_u32(bytes, 80);
    if (bytes.size() == 84 + 50 * std::uint64_t{count}) return parse_binary(bytes, count, name);
  }
  const std::size_t first = bytes.find_first_not_of(" \t\r\n");
  const bool says_solid = first != std::string_view::npos && is_keyword(bytes.substr(first, 5), "solid");
  if (says_solid && bytes.find('\0') == std::string_view::npos) return parse_ascii(bytes, name);
  std::string why = name + ": not an STL file: ";
  why += says_solid ? "it begins with `solid` but holds NUL bytes, as binary STL does (ASCII STL is text)"
                    : "it does not begin with `solid` (ASCII STL)";
  if (bytes.size() < 84)
    throw InputError(why + ", and its " + std::to_string(bytes.size()) + " bytes are too few for binary STL's 84-byte header");
  throw InputError(why + ", and its size, " + std::to_string(bytes.size()) + " bytes, is not 84 + 50 x the " +
                   std::to_string(little_endian_u32(bytes, 80)) + " triangles its header counts (binary STL)");
}

}  // namespace talus::io
