#include "edgefit/core/atomic_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>

namespace edgefit {
namespace {

std::string TempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("edgefit_atomic_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

TEST(AtomicFileTest, WritesAndReadsBack) {
  const std::string path = TempPath("ok.txt");
  ASSERT_TRUE(WriteStringAtomically(path, "hello\n").ok());
  std::string content;
  ASSERT_TRUE(ReadFileToString(path, &content).ok());
  EXPECT_EQ(content, "hello\n");
  std::remove(path.c_str());
}

TEST(AtomicFileTest, FailedWriterLeavesNoFileAndKeepsTheOldOne) {
  const std::string path = TempPath("fail.txt");
  const Status s = WriteFileAtomically(path, [](std::ostream& out) {
    out << "partial";
    return Status::Error("writer gave up");
  });
  EXPECT_FALSE(s.ok());
  EXPECT_FALSE(std::filesystem::exists(path));
  // No temporary file is left behind either.
  for (const auto& entry : std::filesystem::directory_iterator(
           std::filesystem::temp_directory_path())) {
    EXPECT_EQ(entry.path().string().find(path + ".tmp"), std::string::npos);
  }
  ASSERT_TRUE(WriteStringAtomically(path, "old").ok());
  EXPECT_FALSE(WriteFileAtomically(path, [](std::ostream&) { return Status::Error("x"); }).ok());
  std::string content;
  ASSERT_TRUE(ReadFileToString(path, &content).ok());
  EXPECT_EQ(content, "old");
  std::remove(path.c_str());
}

TEST(AtomicFileTest, UnwritableDirectoryNamesThePath) {
  const Status s = WriteStringAtomically("/nonexistent_dir_edgefit/x.txt", "x");
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("/nonexistent_dir_edgefit/x.txt"), std::string::npos);
}

TEST(AtomicFileTest, MissingFileNamesThePath) {
  std::string content;
  const Status s = ReadFileToString("/nonexistent_dir_edgefit/y.txt", &content);
  ASSERT_FALSE(s.ok());
  EXPECT_NE(s.message().find("/nonexistent_dir_edgefit/y.txt"), std::string::npos);
}

}  // namespace
}  // namespace edgefit
