// TimeSeriesCsv: header once, one %.10g row per append, every row on disk as soon as appended.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "io/timeseries_csv.h"
#include "tests/io/scratch_dir.h"

namespace porosph::io {
namespace {

using test::ScratchDir;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(TimeSeriesCsv, WritesHeaderOnceAndOneRowPerAppend) {
  ScratchDir dir;
  const std::string path = dir.file("timeseries.csv");
  TimeSeriesCsv csv(path, {"t", "dt", "kinetic_energy,fluid"});
  EXPECT_EQ(csv.path(), path);
  EXPECT_EQ(read_text(path), "t,dt,\"kinetic_energy,fluid\"\n");
  csv.append({0.0, 1e-4, 1.0 / 3.0});
  csv.append({0.1, 2.5e-12, -123456789012.0});
  // Rows are on disk while the object is alive (flushed per row); %.10g gives 10 digits.
  EXPECT_EQ(read_text(path),
            "t,dt,\"kinetic_energy,fluid\"\n"
            "0,0.0001,0.3333333333\n"
            "0.1,2.5e-12,-1.23456789e+11\n");
}

TEST(TimeSeriesCsv, RowsSurviveEarlyDestructionAndAProcessThatDies) {
  ScratchDir dir;
  const std::string destroyed = dir.file("destroyed.csv");
  {
    TimeSeriesCsv csv(destroyed, {"t", "mass"});
    csv.append({0.5, 2.0});
  }
  EXPECT_EQ(read_text(destroyed), "t,mass\n0.5,2\n");

  // _exit skips destructors and stdio buffers: only rows already flushed reach the file.
  const std::string killed = dir.file("killed.csv");
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    auto* csv = new TimeSeriesCsv(killed, {"t", "mass"});
    csv->append({0.0, 1.0});
    csv->append({0.25, 1.0});
    _exit(0);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(read_text(killed), "t,mass\n0,1\n0.25,1\n");
}

TEST(TimeSeriesCsv, ErrorsNameThePath) {
  ScratchDir dir;
  const std::string unwritable = dir.file("no_such_folder/timeseries.csv");
  try {
    TimeSeriesCsv csv(unwritable, {"t"});
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(unwritable), std::string::npos) << error.what();
  }

  const std::string path = dir.file("timeseries.csv");
  TimeSeriesCsv csv(path, {"t", "dt"});
  csv.append({1.0, 0.5});
  try {
    csv.append({2.0});
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
  }
  EXPECT_EQ(read_text(path), "t,dt\n1,0.5\n");  // the bad row wrote nothing
  EXPECT_THROW(TimeSeriesCsv(dir.file("empty.csv"), {}), std::runtime_error);
}

// A full disk from the start (timeseries.csv links to /dev/full): the error names the file and
// the system's reason, and no empty file stays behind (issue 29).
TEST(TimeSeriesCsv, AFullDiskLeavesNoEmptyFile) {
  ScratchDir dir;
  const std::string path = dir.file("timeseries.csv");
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  std::filesystem::create_symlink("/dev/full", path);
  try {
    TimeSeriesCsv csv(path, {"t", "dt"});
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("No space left on device"), std::string::npos)
        << error.what();
  }
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(path)));
  EXPECT_TRUE(std::filesystem::exists("/dev/full"));
}

}  // namespace
}  // namespace porosph::io
