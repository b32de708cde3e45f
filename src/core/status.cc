#include "edgefit/core/status.h"

namespace edgefit {

Status Status::WithContext(const std::string& context) const {
  if (ok()) return *this;
  return Status::Error(context + ": " + message_);
}

}  // namespace edgefit
