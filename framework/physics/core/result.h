#pragma once
// Results for validation at the library's boundaries (builders, loaders, API inputs).
// Deep solver code never throws; a boundary returns Result<T> with a message that names the field.
#include <optional>
#include <string>
#include <utility>

namespace pba {

/// An error message, e.g. "drop.restitution: must be in [0, 1], got 1.5".
struct Error {
  std::string message;
};

/// Either a value or an Error. Minimal on purpose: check ok(), then value() or error().
template <typename T>
class Result {
 public:
  Result(T value) : value_(std::move(value)) {}              // NOLINT(google-explicit-constructor)
  Result(Error error) : error_(std::move(error.message)) {}  // NOLINT(google-explicit-constructor)

  bool ok() const { return value_.has_value(); }
  explicit operator bool() const { return ok(); }
  const T& value() const& { return *value_; }
  T& value() & { return *value_; }
  T&& value() && { return std::move(*value_); }
  const std::string& error() const { return error_; }

 private:
  std::optional<T> value_;
  std::string error_;
};

/// Result of an operation with no value: empty message means success.
class Status {
 public:
  Status() = default;
  Status(Error error) : error_(std::move(error.message)) {}  // NOLINT(google-explicit-constructor)
  static Status success() { return {}; }
  bool ok() const { return error_.empty(); }
  explicit operator bool() const { return ok(); }
  const std::string& error() const { return error_; }

 private:
  std::string error_;
};

}  // namespace pba
