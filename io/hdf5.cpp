#include "io/hdf5.hpp"

#include <cerrno>
#include <cstring>
#include <sstream>
#include <stdexcept>

#include "core/error.hpp"

namespace suspend::io::h5 {

namespace {
hid_t check(hid_t id, const std::string& what) {
  if (id < 0) throw std::runtime_error("HDF5: " + what);
  return id;
}
void check_status(herr_t s, const std::string& what) {
  if (s < 0) throw std::runtime_error("HDF5: " + what);
}
// A write that fails once the file exists is an output failure (disk full, quota, file size limit): the system's
// reason, which HDF5 leaves in errno, tells the user which.
void check_written(herr_t s, const std::string& what) {
  if (s >= 0) return;
  const int e = errno;
  throw OutputError("cannot " + what + (e ? std::string(" (") + std::strerror(e) + ")" : std::string()));
}
Handle dataspace(const std::vector<hsize_t>& shape) {
  return {check(H5Screate_simple(static_cast<int>(shape.size()), shape.data(), nullptr), "create dataspace"),
          H5Sclose};
}
Handle open_object(hid_t loc, const std::string& path) {
  return {check(H5Oopen(loc, path.c_str(), H5P_DEFAULT), "open object " + path), H5Oclose};
}
template <class T>
void write_any(hid_t loc, const std::string& name, const std::vector<T>& data, const std::vector<hsize_t>& shape,
               hid_t type) {
  hsize_t n = 1;
  for (hsize_t s : shape) n *= s;
  if (n != data.size()) throw std::logic_error("HDF5 write " + name + ": shape does not match data size");
  if (exists(loc, name)) check_status(H5Ldelete(loc, name.c_str(), H5P_DEFAULT), "replace " + name);
  Handle space = dataspace(shape);
  Handle lcpl(check(H5Pcreate(H5P_LINK_CREATE), "plist"), H5Pclose);
  H5Pset_create_intermediate_group(lcpl.id(), 1);
  // Every non-empty dataset carries a Fletcher32 checksum (one chunk, the whole dataset): a flipped bit is a read
  // error, not a silently different restart.
  Handle dcpl(check(H5Pcreate(H5P_DATASET_CREATE), "plist"), H5Pclose);
  if (n > 0 && !shape.empty()) {
    check_status(H5Pset_chunk(dcpl.id(), static_cast<int>(shape.size()), shape.data()), "chunk " + name);
    check_status(H5Pset_fletcher32(dcpl.id()), "checksum " + name);
  }
  Handle set(check(H5Dcreate2(loc, name.c_str(), type, space.id(), lcpl.id(), dcpl.id(), H5P_DEFAULT),
                   "create dataset " + name),
             H5Dclose);
  errno = 0;
  if (n > 0) check_written(H5Dwrite(set.id(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), "write " + name);
}
template <class T>
std::vector<T> read_any(hid_t loc, const std::string& name, std::vector<hsize_t>* shape, hid_t type) {
  if (!exists(loc, name)) throw std::runtime_error("HDF5: dataset " + name + " is missing");
  Handle set(check(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), "open dataset " + name), H5Dclose);
  Handle space(check(H5Dget_space(set.id()), "dataspace of " + name), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.id());
  std::vector<hsize_t> dims(rank > 0 ? rank : 0);
  if (rank > 0) H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr);
  hsize_t n = 1;
  for (hsize_t d : dims) n *= d;
  std::vector<T> out(n);
  if (n > 0) check_status(H5Dread(set.id(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), "read " + name);
  if (shape) *shape = dims;
  return out;
}
Handle attribute_for_write(hid_t loc, const std::string& path, const std::string& name, hid_t type) {
  Handle obj = open_object(loc, path);
  if (H5Aexists(obj.id(), name.c_str()) > 0) H5Adelete(obj.id(), name.c_str());
  Handle space(check(H5Screate(H5S_SCALAR), "scalar space"), H5Sclose);
  return {check(H5Acreate2(obj.id(), name.c_str(), type, space.id(), H5P_DEFAULT, H5P_DEFAULT),
                "create attribute " + name),
          H5Aclose};
}
Handle attribute_for_read(hid_t loc, const std::string& path, const std::string& name) {
  Handle obj = open_object(loc, path);
  if (H5Aexists(obj.id(), name.c_str()) <= 0) throw std::runtime_error("HDF5: attribute " + name + " is missing");
  return {check(H5Aopen(obj.id(), name.c_str(), H5P_DEFAULT), "open attribute " + name), H5Aclose};
}
}  // namespace

Handle& Handle::operator=(Handle&& o) noexcept {
  if (this != &o) {
    reset();
    id_ = o.id_;
    close_ = o.close_;
    o.id_ = -1;
  }
  return *this;
}

void Handle::reset() {
  if (id_ >= 0 && close_) close_(id_);
  id_ = -1;
}

void install_error_handling() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

void initialize_library() {
  // HDF5's exit handler closes the files still open, and crashes in that clean-up on a file whose last flush failed
  // (a full disk). Every file here is closed by its owner, so the handler is not needed.
  H5dont_atexit();
  install_error_handling();
}

File File::create(const std::string& path) {
  install_error_handling();
  File f;
  f.path_ = path;
  errno = 0;
  const hid_t id = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (id < 0) {
    // No room for the file's first block (disk full, quota, file size limit) is an output failure like a failed
    // write; anything else (a missing or read-only folder) is not.
    const int e = errno;
    const std::string reason = e ? std::string(" (") + std::strerror(e) + ")" : std::string();
    if (e == ENOSPC || e == EDQUOT || e == EFBIG || e == EIO)
      throw OutputError("cannot write " + path + ", the file could not be created" + reason);
    throw std::runtime_error("HDF5: cannot create " + path + reason);
  }
  f.h_ = Handle(id, H5Fclose);
  return f;
}

File File::open(const std::string& path, bool writable) {
  install_error_handling();
  File f;
  f.path_ = path;
  f.h_ = Handle(check(H5Fopen(path.c_str(), writable ? H5F_ACC_RDWR : H5F_ACC_RDONLY, H5P_DEFAULT),
                      "cannot open " + path + " (missing, unreadable or not an HDF5 file)"),
                H5Fclose);
  return f;
}

void File::flush() const {
  errno = 0;
  check_written(H5Fflush(h_.id(), H5F_SCOPE_GLOBAL), "write " + path_);
}

bool exists(hid_t loc, const std::string& path) {
  std::string prefix;
  std::stringstream ss(path);
  for (std::string part; std::getline(ss, part, '/');) {
    if (part.empty()) continue;
    if (!prefix.empty()) prefix += '/';
    prefix += part;
    if (H5Lexists(loc, prefix.c_str(), H5P_DEFAULT) <= 0) return false;
  }
  return true;
}

bool openable(hid_t loc, const std::string& path) {
  if (!exists(loc, path)) return false;
  const hid_t id = H5Oopen(loc, path.c_str(), H5P_DEFAULT);
  if (id < 0) return false;
  H5Oclose(id);
  return true;
}

void copy_object(hid_t from, hid_t to, const std::string& path) {
  Handle lcpl(check(H5Pcreate(H5P_LINK_CREATE), "plist"), H5Pclose);
  H5Pset_create_intermediate_group(lcpl.id(), 1);
  errno = 0;
  check_written(H5Ocopy(from, path.c_str(), to, path.c_str(), H5P_DEFAULT, lcpl.id()), "copy " + path);
}

void copy_root_attributes(hid_t from, hid_t to) {
  const auto copy = [](hid_t loc, const char* name, const H5A_info_t*, void* data) -> herr_t {
    const hid_t target = *static_cast<hid_t*>(data);
    Handle a(H5Aopen(loc, name, H5P_DEFAULT), H5Aclose);
    if (!a) return -1;
    Handle type(H5Aget_type(a.id()), H5Tclose), space(H5Aget_space(a.id()), H5Sclose);
    std::vector<char> value(H5Aget_storage_size(a.id()) + H5Tget_size(type.id()));
    if (H5Aread(a.id(), type.id(), value.data()) < 0) return -1;
    if (H5Aexists(target, name) > 0) H5Adelete(target, name);
    Handle b(H5Acreate2(target, name, type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
    return b && H5Awrite(b.id(), type.id(), value.data()) >= 0 ? 0 : -1;
  };
  hsize_t index = 0;
  errno = 0;
  check_written(H5Aiterate2(from, H5_INDEX_NAME, H5_ITER_NATIVE, &index, copy, &to), "copy the file attributes");
}

void create_groups(hid_t loc, const std::string& path) {
  if (exists(loc, path)) return;
  Handle lcpl(check(H5Pcreate(H5P_LINK_CREATE), "plist"), H5Pclose);
  H5Pset_create_intermediate_group(lcpl.id(), 1);
  Handle g(check(H5Gcreate2(loc, path.c_str(), lcpl.id(), H5P_DEFAULT, H5P_DEFAULT), "create group " + path),
           H5Gclose);
}

void write(hid_t loc, const std::string& name, const std::vector<double>& data, const std::vector<hsize_t>& shape) {
  write_any(loc, name, data, shape, H5T_NATIVE_DOUBLE);
}
void write(hid_t loc, const std::string& name, const std::vector<std::int64_t>& data,
           const std::vector<hsize_t>& shape) {
  write_any(loc, name, data, shape, H5T_NATIVE_INT64);
}
std::vector<double> read_doubles(hid_t loc, const std::string& name, std::vector<hsize_t>* shape) {
  return read_any<double>(loc, name, shape, H5T_NATIVE_DOUBLE);
}
std::vector<std::int64_t> read_ints(hid_t loc, const std::string& name, std::vector<hsize_t>* shape) {
  return read_any<std::int64_t>(loc, name, shape, H5T_NATIVE_INT64);
}
std::vector<hsize_t> shape_of(hid_t loc, const std::string& name) {
  Handle set(check(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), "open dataset " + name), H5Dclose);
  Handle space(check(H5Dget_space(set.id()), "dataspace of " + name), H5Sclose);
  std::vector<hsize_t> dims(H5Sget_simple_extent_ndims(space.id()));
  H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr);
  return dims;
}

void set_attribute(hid_t loc, const std::string& path, const std::string& name, const std::string& value) {
  Handle type(check(H5Tcopy(H5T_C_S1), "string type"), H5Tclose);
  H5Tset_size(type.id(), value.empty() ? 1 : value.size());
  H5Tset_strpad(type.id(), H5T_STR_NULLPAD);
  Handle a = attribute_for_write(loc, path, name, type.id());
  const std::string padded = value.empty() ? std::string(1, '\0') : value;
  check_status(H5Awrite(a.id(), type.id(), padded.data()), "write attribute " + name);
}
void set_attribute(hid_t loc, const std::string& path, const std::string& name, double value) {
  Handle a = attribute_for_write(loc, path, name, H5T_NATIVE_DOUBLE);
  check_status(H5Awrite(a.id(), H5T_NATIVE_DOUBLE, &value), "write attribute " + name);
}
void set_attribute(hid_t loc, const std::string& path, const std::string& name, std::int64_t value) {
  Handle a = attribute_for_write(loc, path, name, H5T_NATIVE_INT64);
  check_status(H5Awrite(a.id(), H5T_NATIVE_INT64, &value), "write attribute " + name);
}
std::string string_attribute(hid_t loc, const std::string& path, const std::string& name) {
  Handle a = attribute_for_read(loc, path, name);
  Handle type(check(H5Aget_type(a.id()), "attribute type"), H5Tclose);
  if (H5Tget_class(type.id()) != H5T_STRING) throw std::runtime_error("HDF5: attribute " + name + " is not text");
  const std::size_t n = H5Tget_size(type.id());
  std::string s(n, '\0');
  check_status(H5Aread(a.id(), type.id(), s.data()), "read attribute " + name);
  s.resize(s.find('\0') == std::string::npos ? n : s.find('\0'));
  return s;
}
double double_attribute(hid_t loc, const std::string& path, const std::string& name) {
  Handle a = attribute_for_read(loc, path, name);
  double v = 0.0;
  check_status(H5Aread(a.id(), H5T_NATIVE_DOUBLE, &v), "read attribute " + name);
  return v;
}
bool has_attribute(hid_t loc, const std::string& path, const std::string& name) {
  const htri_t e = H5Aexists_by_name(loc, path.c_str(), name.c_str(), H5P_DEFAULT);
  check_status(e, "look up attribute " + name);
  return e > 0;
}
std::int64_t int_attribute(hid_t loc, const std::string& path, const std::string& name) {
  Handle a = attribute_for_read(loc, path, name);
  std::int64_t v = 0;
  check_status(H5Aread(a.id(), H5T_NATIVE_INT64, &v), "read attribute " + name);
  return v;
}

Table Table::create(hid_t loc, const std::string& name, hsize_t width, hsize_t chunk_rows, bool integer) {
  Table t;
  t.width_ = width;
  t.vector_ = (width == 1);
  const int rank = t.vector_ ? 1 : 2;
  hsize_t dims[2] = {0, width}, maxdims[2] = {H5S_UNLIMITED, width}, chunk[2] = {chunk_rows, width};
  Handle space(check(H5Screate_simple(rank, dims, maxdims), "table space"), H5Sclose);
  Handle dcpl(check(H5Pcreate(H5P_DATASET_CREATE), "plist"), H5Pclose);
  H5Pset_chunk(dcpl.id(), rank, chunk);
  Handle lcpl(check(H5Pcreate(H5P_LINK_CREATE), "plist"), H5Pclose);
  H5Pset_create_intermediate_group(lcpl.id(), 1);
  t.set_ = Handle(check(H5Dcreate2(loc, name.c_str(), integer ? H5T_STD_I64LE : H5T_NATIVE_DOUBLE, space.id(),
                                   lcpl.id(), dcpl.id(),
                                   H5P_DEFAULT),
                        "create table " + name),
                  H5Dclose);
  return t;
}

Table Table::open(hid_t loc, const std::string& name) {
  Table t;
  t.set_ = Handle(check(H5Dopen2(loc, name.c_str(), H5P_DEFAULT), "open table " + name), H5Dclose);
  Handle space(check(H5Dget_space(t.set_.id()), "table space"), H5Sclose);
  const int rank = H5Sget_simple_extent_ndims(space.id());
  hsize_t dims[2] = {0, 1};
  H5Sget_simple_extent_dims(space.id(), dims, nullptr);
  t.vector_ = (rank == 1);
  t.rows_ = dims[0];
  t.width_ = t.vector_ ? 1 : dims[1];
  return t;
}

void Table::append(const double* row) { append_rows(row, 1); }

void Table::append_rows(const double* rows, hsize_t count) {
  if (count == 0) return;
  const int rank = vector_ ? 1 : 2;
  hsize_t newdims[2] = {rows_ + count, width_};
  errno = 0;
  check_written(H5Dset_extent(set_.id(), newdims), "extend a table");
  Handle file_space(check(H5Dget_space(set_.id()), "table space"), H5Sclose);
  hsize_t start[2] = {rows_, 0}, size[2] = {count, width_};
  H5Sselect_hyperslab(file_space.id(), H5S_SELECT_SET, start, nullptr, size, nullptr);
  Handle mem(check(H5Screate_simple(rank, size, nullptr), "rows space"), H5Sclose);
  check_written(H5Dwrite(set_.id(), H5T_NATIVE_DOUBLE, mem.id(), file_space.id(), H5P_DEFAULT, rows),
                "append table rows");
  rows_ += count;
}

std::vector<double> Table::read_rows(hsize_t count) const {
  if (count > rows_) throw std::runtime_error("HDF5: a table has fewer rows than asked for");
  std::vector<double> out(count * width_);
  if (count == 0) return out;
  const int rank = vector_ ? 1 : 2;
  Handle file_space(check(H5Dget_space(set_.id()), "table space"), H5Sclose);
  hsize_t start[2] = {0, 0}, size[2] = {count, width_};
  H5Sselect_hyperslab(file_space.id(), H5S_SELECT_SET, start, nullptr, size, nullptr);
  Handle mem(check(H5Screate_simple(rank, size, nullptr), "rows space"), H5Sclose);
  check_status(H5Dread(set_.id(), H5T_NATIVE_DOUBLE, mem.id(), file_space.id(), H5P_DEFAULT, out.data()),
               "read table rows");
  return out;
}

void Table::truncate(hsize_t rows) {
  if (rows > rows_) throw std::runtime_error("HDF5: cannot truncate a table to more rows than it has");
  hsize_t newdims[2] = {rows, width_};
  check_status(H5Dset_extent(set_.id(), newdims), "truncate table");
  rows_ = rows;
}

}  // namespace suspend::io::h5
