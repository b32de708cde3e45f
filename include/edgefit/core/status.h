// Status: the result of an operation that can fail on bad user input.
//
// No exceptions cross the library's core (STYLE.md, 6). Functions that read
// files or validate user data return a Status; a failed Status carries one
// line that names the file and the problem, ready for the command line to
// print before it exits with code 2. Programmer errors are CHECKs instead.
#ifndef EDGEFIT_CORE_STATUS_H_
#define EDGEFIT_CORE_STATUS_H_

#include <string>
#include <utility>

namespace edgefit {

class Status {
 public:
  // An OK status.
  Status() = default;

  static Status Ok() { return Status(); }
  // A failure with a one-line message, e.g. "scan.ptx: line 12: expected 4 numbers".
  static Status Error(std::string message) { return Status(std::move(message)); }

  bool ok() const { return !failed_; }
  const std::string& message() const { return message_; }

  // Returns a failure whose message is "<context>: <message>"; OK stays OK.
  Status WithContext(const std::string& context) const;

 private:
  explicit Status(std::string message) : failed_(true), message_(std::move(message)) {}

  bool failed_ = false;
  std::string message_;
};

}  // namespace edgefit

// Returns early from the calling function if `expr` is a failed Status.
#define EDGEFIT_RETURN_IF_ERROR(expr)          \
  do {                                         \
    ::edgefit::Status edgefit_status_ = (expr); \
    if (!edgefit_status_.ok()) return edgefit_status_; \
  } while (0)

#endif  // EDGEFIT_CORE_STATUS_H_
