#include "talus/io/hdf5_file.h"

#include <hdf5.h>

#include <atomic>
#include <cstring>
#include <mutex>
#include <stdexcept>

namespace talus::io {

static_assert(sizeof(hid_t) == sizeof(std::int64_t), "hid_t is stored as std::int64_t");

namespace {

constexpr const char* kChecksum = "fnv1a64";

// HDF5 prints its error stack to stderr by default; Talus reports its own one-line errors.
void silence_hdf5() {
  static std::once_flag once;
  std::call_once(once, [] { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); });
}

// Closes an HDF5 handle with the matching call at scope exit.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  bool ok() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void check(bool ok, const std::string& what) {
  if (!ok) throw std::runtime_error(what);
}

void write_checksum(hid_t object, std::uint64_t sum, const std::string& path) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(H5Acreate2(object, kChecksum, H5T_STD_U64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  check(attr.ok() && H5Awrite(attr.get(), H5T_NATIVE_UINT64, &sum) >= 0, "cannot write the checksum of " + path);
}

}  // namespace

std::uint64_t fnv1a64(const void* data, std::size_t bytes) {
  const auto* p = static_cast<const unsigned char*>(data);
  std::uint64_t h = 14695981039346656037ull;
  for (std::size_t k = 0; k < bytes; ++k) {
    h ^= p[k];
    h *= 1099511628211ull;
  }
  return h;
}

Hdf5Writer::Hdf5Writer() {
  silence_hdf5();
  // An in-memory file: the name only has to be unique among open files.
  static std::atomic<int> counter{0};
  const std::string name = "talus-memory-" + std::to_string(counter++);
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  check(fapl.ok() && H5Pset_fapl_core(fapl.get(), 1 << 20, false) >= 0, "HDF5: cannot set up an in-memory file");
  file_ = H5Fcreate(name.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get());
  check(file_ >= 0, "HDF5: cannot create an in-memory file");
}

Hdf5Writer::~Hdf5Writer() {
  if (file_ >= 0) H5Fclose(file_);
}

void Hdf5Writer::write_raw(const std::string& path, const void* data, std::size_t count, std::size_t columns,
                           std::int64_t file_type, std::int64_t memory_type, std::size_t element_bytes) {
  if (columns == 0 || count % columns != 0)
    throw std::logic_error("Hdf5Writer: " + path + ": " + std::to_string(count) + " values in rows of " +
                           std::to_string(columns));
  const hsize_t dims[2] = {count / columns, columns};
  Handle space(H5Screate_simple(columns > 1 ? 2 : 1, dims, nullptr), H5Sclose);
  Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  H5Pset_create_intermediate_group(lcpl.get(), 1);
  Handle set(H5Dcreate2(file_, path.c_str(), file_type, space.get(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  check(set.ok(), "HDF5: cannot create dataset " + path);
  if (count > 0) check(H5Dwrite(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0, "HDF5: cannot write " + path);
  write_checksum(set.get(), fnv1a64(data, count * element_bytes), path);
}

void Hdf5Writer::write(const std::string& path, std::span<const double> v, std::size_t columns) {
  write_raw(path, v.data(), v.size(), columns, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, sizeof(double));
}
void Hdf5Writer::write(const std::string& path, std::span<const std::uint64_t> v, std::size_t columns) {
  write_raw(path, v.data(), v.size(), columns, H5T_STD_U64LE, H5T_NATIVE_UINT64, sizeof(std::uint64_t));
}
void Hdf5Writer::write(const std::string& path, std::span<const std::uint32_t> v, std::size_t columns) {
  write_raw(path, v.data(), v.size(), columns, H5T_STD_U32LE, H5T_NATIVE_UINT32, sizeof(std::uint32_t));
}
void Hdf5Writer::write(const std::string& path, std::span<const std::int32_t> v, std::size_t columns) {
  write_raw(path, v.data(), v.size(), columns, H5T_STD_I32LE, H5T_NATIVE_INT32, sizeof(std::int32_t));
}
void Hdf5Writer::write(const std::string& path, std::span<const std::uint16_t> v, std::size_t columns) {
  write_raw(path, v.data(), v.size(), columns, H5T_STD_U16LE, H5T_NATIVE_UINT16, sizeof(std::uint16_t));
}

void Hdf5Writer::write_text(const std::string& path, std::string_view text) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), text.size() + 1);  // HDF5 strings cannot be empty: room for the terminator
  H5Tset_strpad(type.get(), H5T_STR_NULLTERM);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle lcpl(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  H5Pset_create_intermediate_group(lcpl.get(), 1);
  Handle set(H5Dcreate2(file_, path.c_str(), type.get(), space.get(), lcpl.get(), H5P_DEFAULT, H5P_DEFAULT), H5Dclose);
  check(set.ok(), "HDF5: cannot create dataset " + path);
  const std::string terminated(text);
  check(H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, terminated.c_str()) >= 0, "HDF5: cannot write " + path);
  write_checksum(set.get(), fnv1a64(text.data(), text.size()), path);
}

void Hdf5Writer::attribute(const std::string& name, std::string_view value) {
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), value.size() + 1);
  H5Tset_strpad(type.get(), H5T_STR_NULLTERM);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(H5Acreate2(file_, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  const std::string terminated(value);
  check(attr.ok() && H5Awrite(attr.get(), type.get(), terminated.c_str()) >= 0, "HDF5: cannot write attribute " + name);
}

void Hdf5Writer::attribute(const std::string& name, std::int64_t value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr(H5Acreate2(file_, name.c_str(), H5T_STD_I64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  check(attr.ok() && H5Awrite(attr.get(), H5T_NATIVE_INT64, &value) >= 0, "HDF5: cannot write attribute " + name);
}

std::vector<char> Hdf5Writer::image() {
  check(H5Fflush(file_, H5F_SCOPE_GLOBAL) >= 0, "HDF5: cannot flush the in-memory file");
  const ssize_t size = H5Fget_file_image(file_, nullptr, 0);
  check(size > 0, "HDF5: cannot read back the in-memory file");
  std::vector<char> bytes(static_cast<std::size_t>(size));
  check(H5Fget_file_image(file_, bytes.data(), bytes.size()) == size, "HDF5: cannot read back the in-memory file");
  return bytes;
}

Hdf5Reader::Hdf5Reader(const std::filesystem::path& path) : path_(path) {
  silence_hdf5();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) fail("no such file");
  if (H5Fis_hdf5(path.c_str()) <= 0) fail("not an HDF5 file");
  file_ = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file_ < 0) fail("unreadable HDF5 file (truncated or corrupt)");
}

Hdf5Reader::~Hdf5Reader() {
  if (file_ >= 0) H5Fclose(file_);
}

void Hdf5Reader::fail(const std::string& what) const { throw std::runtime_error(path_.string() + ": " + what); }

bool Hdf5Reader::has(const std::string& path) const {
  // Checks each link on the way, as H5Lexists requires.
  std::size_t pos = 0;
  while (true) {
    pos = path.find('/', pos + 1);
    const std::string prefix = path.substr(0, pos);
    if (H5Lexists(file_, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
    if (pos == std::string::npos) return true;
  }
}

std::size_t Hdf5Reader::count(const std::string& path, std::size_t columns) const {
  if (!has(path)) fail("missing dataset " + path);
  Handle set(H5Dopen2(file_, path.c_str(), H5P_DEFAULT), H5Dclose);
  if (!set.ok()) fail("unreadable dataset " + path);
  Handle space(H5Dget_space(set.get()), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.get());
  hsize_t dims[2] = {0, 1};
  if (rank != (columns > 1 ? 2 : 1) || H5Sget_simple_extent_dims(space.get(), dims, nullptr) != rank ||
      (rank == 2 && dims[1] != columns))
    fail("dataset " + path + " has the wrong shape (expected " +
         (columns > 1 ? "rows x " + std::to_string(columns) : std::string("one dimension")) + ")");
  return static_cast<std::size_t>(dims[0] * (rank == 2 ? dims[1] : 1));
}

void Hdf5Reader::read_raw(const std::string& path, void* out, std::size_t element_bytes, std::size_t n,
                          std::int64_t memory_type) const {
  Handle set(H5Dopen2(file_, path.c_str(), H5P_DEFAULT), H5Dclose);
  Handle type(H5Dget_type(set.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5Tget_class(memory_type) || H5Tget_size(type.get()) != element_bytes)
    fail("dataset " + path + " has the wrong element type");
  if (n > 0 && H5Dread(set.get(), memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out) < 0)
    fail("cannot read dataset " + path + " (corrupt file)");
  Handle attr(H5Aopen(set.get(), kChecksum, H5P_DEFAULT), H5Aclose);
  std::uint64_t stored = 0;
  if (!attr.ok() || H5Aread(attr.get(), H5T_NATIVE_UINT64, &stored) < 0) fail("dataset " + path + " has no checksum");
  if (stored != fnv1a64(out, n * element_bytes)) fail("dataset " + path + " does not match its checksum (corrupt file)");
}

std::vector<double> Hdf5Reader::read_double(const std::string& path, std::size_t columns) const {
  std::vector<double> out(count(path, columns));
  read_raw(path, out.data(), sizeof(double), out.size(), H5T_NATIVE_DOUBLE);
  return out;
}
std::vector<std::uint64_t> Hdf5Reader::read_u64(const std::string& path, std::size_t columns) const {
  std::vector<std::uint64_t> out(count(path, columns));
  read_raw(path, out.data(), sizeof(std::uint64_t), out.size(), H5T_NATIVE_UINT64);
  return out;
}
std::vector<std::uint32_t> Hdf5Reader::read_u32(const std::string& path, std::size_t columns) const {
  std::vector<std::uint32_t> out(count(path, columns));
  read_raw(path, out.data(), sizeof(std::uint32_t), out.size(), H5T_NATIVE_UINT32);
  return out;
}
std::vector<std::int32_t> Hdf5Reader::read_i32(const std::string& path, std::size_t columns) const {
  std::vector<std::int32_t> out(count(path, columns));
  read_raw(path, out.data(), sizeof(std::int32_t), out.size(), H5T_NATIVE_INT32);
  return out;
}
std::vector<std::uint16_t> Hdf5Reader::read_u16(const std::string& path, std::size_t columns) const {
  std::vector<std::uint16_t> out(count(path, columns));
  read_raw(path, out.data(), sizeof(std::uint16_t), out.size(), H5T_NATIVE_UINT16);
  return out;
}

void Hdf5Reader::read_rows_raw(const std::string& path, void* out, std::size_t element_bytes, std::size_t columns,
                               Rows rows, std::int64_t memory_type) const {
  const std::size_t total = count(path, columns) / columns;
  if (rows.first + rows.count > total)
    fail("dataset " + path + " has " + std::to_string(total) + " rows, not the " +
         std::to_string(rows.first + rows.count) + " a share needs");
  Handle set(H5Dopen2(file_, path.c_str(), H5P_DEFAULT), H5Dclose);
  Handle type(H5Dget_type(set.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5Tget_class(memory_type) || H5Tget_size(type.get()) != element_bytes)
    fail("dataset " + path + " has the wrong element type");
  if (rows.count == 0) return;
  Handle file_space(H5Dget_space(set.get()), H5Sclose);
  const int dims = columns > 1 ? 2 : 1;
  const hsize_t start[2] = {rows.first, 0}, block[2] = {rows.count, columns};
  Handle memory_space(H5Screate_simple(dims, block, nullptr), H5Sclose);
  if (H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, block, nullptr) < 0 ||
      H5Dread(set.get(), memory_type, memory_space.get(), file_space.get(), H5P_DEFAULT, out) < 0)
    fail("cannot read rows of dataset " + path + " (corrupt file)");
}

std::vector<double> Hdf5Reader::read_double_rows(const std::string& path, std::size_t columns, Rows rows) const {
  std::vector<double> out(rows.count * columns);
  read_rows_raw(path, out.data(), sizeof(double), columns, rows, H5T_NATIVE_DOUBLE);
  return out;
}
std::vector<std::uint32_t> Hdf5Reader::read_u32_rows(const std::string& path, std::size_t columns, Rows rows) const {
  std::vector<std::uint32_t> out(rows.count * columns);
  read_rows_raw(path, out.data(), sizeof(std::uint32_t), columns, rows, H5T_NATIVE_UINT32);
  return out;
}
std::vector<std::int32_t> Hdf5Reader::read_i32_rows(const std::string& path, std::size_t columns, Rows rows) const {
  std::vector<std::int32_t> out(rows.count * columns);
  read_rows_raw(path, out.data(), sizeof(std::int32_t), columns, rows, H5T_NATIVE_INT32);
  return out;
}
std::vector<std::uint16_t> Hdf5Reader::read_u16_rows(const std::string& path, std::size_t columns, Rows rows) const {
  std::vector<std::uint16_t> out(rows.count * columns);
  read_rows_raw(path, out.data(), sizeof(std::uint16_t), columns, rows, H5T_NATIVE_UINT16);
  return out;
}

std::string Hdf5Reader::read_text(const std::string& path) const {
  if (!has(path)) fail("missing dataset " + path);
  Handle set(H5Dopen2(file_, path.c_str(), H5P_DEFAULT), H5Dclose);
  Handle type(H5Dget_type(set.get()), H5Tclose);
  if (!set.ok() || H5Tget_class(type.get()) != H5T_STRING) fail("dataset " + path + " is not text");
  std::string buffer(H5Tget_size(type.get()), '\0');
  if (H5Dread(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0)
    fail("cannot read dataset " + path + " (corrupt file)");
  buffer.resize(std::strlen(buffer.c_str()));
  Handle attr(H5Aopen(set.get(), kChecksum, H5P_DEFAULT), H5Aclose);
  std::uint64_t stored = 0;
  if (!attr.ok() || H5Aread(attr.get(), H5T_NATIVE_UINT64, &stored) < 0) fail("dataset " + path + " has no checksum");
  if (stored != fnv1a64(buffer.data(), buffer.size())) fail("dataset " + path + " does not match its checksum (corrupt file)");
  return buffer;
}

bool Hdf5Reader::has_attribute(const std::string& name) const { return H5Aexists(file_, name.c_str()) > 0; }

std::string Hdf5Reader::string_attribute(const std::string& name) const {
  if (!has_attribute(name)) fail("missing attribute " + name);
  Handle attr(H5Aopen(file_, name.c_str(), H5P_DEFAULT), H5Aclose);
  Handle type(H5Aget_type(attr.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING) fail("attribute " + name + " is not text");
  std::string buffer(H5Tget_size(type.get()), '\0');
  if (H5Aread(attr.get(), type.get(), buffer.data()) < 0) fail("cannot read attribute " + name);
  buffer.resize(std::strlen(buffer.c_str()));
  return buffer;
}

std::int64_t Hdf5Reader::int_attribute(const std::string& name) const {
  if (!has_attribute(name)) fail("missing attribute " + name);
  Handle attr(H5Aopen(file_, name.c_str(), H5P_DEFAULT), H5Aclose);
  Handle type(H5Aget_type(attr.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_INTEGER) fail("attribute " + name + " is not an integer");
  std::int64_t value = 0;
  if (H5Aread(attr.get(), H5T_NATIVE_INT64, &value) < 0) fail("cannot read attribute " + name);
  return value;
}

}  // namespace talus::io
