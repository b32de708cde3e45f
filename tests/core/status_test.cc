#include "edgefit/core/status.h"

#include <gtest/gtest.h>

namespace edgefit {
namespace {

Status FailsThrough() {
  EDGEFIT_RETURN_IF_ERROR(Status::Error("inner"));
  return Status::Ok();
}

TEST(StatusTest, OkAndErrorCarryTheirMessage) {
  EXPECT_TRUE(Status::Ok().ok());
  const Status error = Status::Error("scan.ptx: line 3: bad number");
  EXPECT_FALSE(error.ok());
  EXPECT_EQ(error.message(), "scan.ptx: line 3: bad number");
  EXPECT_EQ(error.WithContext("load").message(), "load: scan.ptx: line 3: bad number");
  EXPECT_TRUE(Status::Ok().WithContext("load").ok());
}

TEST(StatusTest, ReturnIfErrorPropagates) {
  const Status s = FailsThrough();
  EXPECT_FALSE(s.ok());
  EXPECT_EQ(s.message(), "inner");
}

}  // namespace
}  // namespace edgefit
