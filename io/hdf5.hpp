// A thin RAII layer over the HDF5 C API: files, groups, whole datasets, attributes, and growable tables
// (chunked datasets with an unlimited first dimension, for time series and restarts that truncate them).
#pragma once
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace suspend::io::h5 {

// Owns one HDF5 identifier and closes it with the right function.
class Handle {
 public:
  Handle() = default;
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
  Handle& operator=(Handle&& o) noexcept;
  ~Handle() { reset(); }
  void reset();
  hid_t id() const { return id_; }
  explicit operator bool() const { return id_ >= 0; }

 private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

class File {
 public:
  static File create(const std::string& path);  // truncates
  static File open(const std::string& path, bool writable);
  hid_t id() const { return h_.id(); }
  void flush() const;
  void close() { h_.reset(); }
  const std::string& path() const { return path_; }

 private:
  Handle h_;
  std::string path_;
};

bool exists(hid_t loc, const std::string& path);  // any link, nested paths allowed
// Whether the object at `path` can be opened (a link can outlive its object in a file whose last write failed).
bool openable(hid_t loc, const std::string& path);
// Copies the object at `path` (a group with everything in it, or a dataset) from one file to the same path in another.
void copy_object(hid_t from, hid_t to, const std::string& path);
// Copies every attribute of the root group of one file to another's.
void copy_root_attributes(hid_t from, hid_t to);
void create_groups(hid_t loc, const std::string& path);  // like mkdir -p

// Whole datasets: shape given explicitly (row-major).
void write(hid_t loc, const std::string& name, const std::vector<double>& data, const std::vector<hsize_t>& shape);
void write(hid_t loc, const std::string& name, const std::vector<std::int64_t>& data,
           const std::vector<hsize_t>& shape);
std::vector<double> read_doubles(hid_t loc, const std::string& name, std::vector<hsize_t>* shape = nullptr);
std::vector<std::int64_t> read_ints(hid_t loc, const std::string& name, std::vector<hsize_t>* shape = nullptr);
std::vector<hsize_t> shape_of(hid_t loc, const std::string& name);

// Attributes on a group or dataset (object at `path` relative to loc; "." for loc itself).
void set_attribute(hid_t loc, const std::string& path, const std::string& name, const std::string& value);
void set_attribute(hid_t loc, const std::string& path, const std::string& name, double value);
void set_attribute(hid_t loc, const std::string& path, const std::string& name, std::int64_t value);
std::string string_attribute(hid_t loc, const std::string& path, const std::string& name);
double double_attribute(hid_t loc, const std::string& path, const std::string& name);
std::int64_t int_attribute(hid_t loc, const std::string& path, const std::string& name);
bool has_attribute(hid_t loc, const std::string& path, const std::string& name);

// A growable table of doubles: rows of `width` values, appended one at a time.
class Table {
 public:
  // integer: stored as 64-bit integers (counts); rows are still passed and read as doubles, which HDF5 converts.
  static Table create(hid_t loc, const std::string& name, hsize_t width, hsize_t chunk_rows = 256,
                      bool integer = false);
  static Table open(hid_t loc, const std::string& name);
  void append(const double* row);
  void append_rows(const double* rows, hsize_t count);  // count rows of width() values, row-major
  std::vector<double> read_rows(hsize_t count) const;   // the first count rows, without touching later chunks
  void truncate(hsize_t rows);  // keep the first `rows` rows (restart)
  hsize_t rows() const { return rows_; }
  hsize_t width() const { return width_; }

 private:
  Handle set_;
  hsize_t rows_ = 0, width_ = 1;
  bool vector_ = true;  // 1-D dataset when width == 1
};

// Turns HDF5's error stack into C++ exceptions (and silences its automatic printing). Failed writes, flushes and
// table extensions throw OutputError (core/error.hpp), other failures std::runtime_error.
void install_error_handling();
// Called by a program first, before any other HDF5 call: error handling, and no HDF5 exit handler.
void initialize_library();

}  // namespace suspend::io::h5
