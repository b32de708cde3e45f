#include "edgefit/core/mapped_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "edgefit/core/atomic_file.h"

namespace edgefit {
namespace {

std::string MappedTempPath(const std::string& name) {
  return (std::filesystem::temp_directory_path() /
          ("edgefit_mapped_" + std::to_string(::getpid()) + "_" + name))
      .string();
}

// Three pages and a bit, so that a release drops whole pages and keeps
// the partial one.
std::string Text() {
  std::string text;
  for (int i = 0; text.size() < 3 * 4096 + 100; ++i) text += std::to_string(i) + " 0.5 1.5\n";
  return text;
}

TEST(MappedFileTest, ViewsTheFileAndReadsReleasedPagesAgain) {
  const std::string path = MappedTempPath("text.ptx");
  const std::string text = Text();
  ASSERT_TRUE(WriteStringAtomically(path, text).ok());
  MappedFile file;
  ASSERT_TRUE(file.Open(path).ok());
  ASSERT_EQ(file.view(), text);
  file.Release(file.view().data() + 2 * 4096 + 17);  // two whole pages go
  EXPECT_EQ(file.view(), text);                       // and are read again
  file.Release(file.view().data() + file.view().size());
  EXPECT_EQ(file.view(), text);
  std::remove(path.c_str());
}

TEST(MappedFileTest, EmptyFileMapsToAnEmptyView) {
  const std::string path = MappedTempPath("empty.ptx");
  ASSERT_TRUE(WriteStringAtomically(path, "").ok());
  MappedFile file;
  ASSERT_TRUE(file.Open(path).ok());
  EXPECT_TRUE(file.view().empty());
  file.Release(file.view().data());  // nothing to release
  std::remove(path.c_str());
}

TEST(MappedFileTest, MissingFileAndDirectoryFailWithTheirName) {
  MappedFile file;
  const std::string missing = MappedTempPath("missing.ptx");
  const Status absent = file.Open(missing);
  ASSERT_FALSE(absent.ok());
  EXPECT_NE(absent.message().find(missing + ": cannot open"), std::string::npos)
      << absent.message();
  const std::string directory = std::filesystem::temp_directory_path().string();
  const Status folder = file.Open(directory);
  ASSERT_FALSE(folder.ok());
  EXPECT_NE(folder.message().find("not a regular file"), std::string::npos) << folder.message();
  EXPECT_TRUE(file.view().empty());
}

}  // namespace
}  // namespace edgefit
