#pragma once
// PvdSeries: a ParaView collection file (name.pvd) listing (time, file) pairs, rewritten
// atomically (io/atomic_file.h) after every add(), so ParaView can open a run in progress and
// File > Reload picks up the new frames. The file names are stored relative to the .pvd's
// directory, so a results directory can be moved as a whole.
#include <filesystem>
#include <string>
#include <vector>

namespace talus::io {

class PvdSeries {
 public:
  struct Entry {
    double time = 0;    ///< s
    std::string file;   ///< relative to the .pvd's directory
  };

  explicit PvdSeries(std::filesystem::path pvd_path);

  // Appends a frame and rewrites the .pvd. `file` may be absolute or relative to the .pvd's
  // directory. Throws std::system_error if the file cannot be written.
  void add(double time, const std::filesystem::path& file);
  // Appends several frames (relative names) and rewrites the .pvd once: a resumed run.
  void add_all(const std::vector<Entry>& entries);

  const std::filesystem::path& path() const { return path_; }
  const std::vector<Entry>& entries() const { return entries_; }
  std::string xml() const;  // the .pvd contents

 private:
  std::filesystem::path path_;
  std::vector<Entry> entries_;
};

}  // namespace talus::io
