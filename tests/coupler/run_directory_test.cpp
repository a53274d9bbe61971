// The run directory's lock, earlier-run detection, --overwrite, the checkpoint's scene check and
// `coupler status`, in process (coupler/run_directory.h, coupler/run_status.h, issue 29).
#include "coupler/run_directory.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "coupler/checkpoint.h"
#include "coupler/run_status.h"

namespace porosph::coupler {
namespace {

namespace fs = std::filesystem;

std::string fresh_dir(const std::string& name) {
  const fs::path dir =
      fs::temp_directory_path() / ("porosph-rundir-" + std::to_string(getpid()) + "-" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

void write(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

TEST(RunDirectoryLock, ASecondLockIsRefusedNamingTheHolder) {
  const std::string dir = fresh_dir("lock") + "/out";
  {
    const RunDirectoryLock lock(dir);  // creates the directory
    const LockProbe probe = probe_run_directory_lock(dir);
    EXPECT_TRUE(probe.held);
    EXPECT_EQ(probe.owner, std::to_string(getpid()) + " " + host_name());
    try {
      const RunDirectoryLock second(dir);
      ADD_FAILURE() << "a second lock was granted";
    } catch (const RunDirectoryError& e) {
      EXPECT_NE(std::string(e.what()).find("in use: coupler pid " + std::to_string(getpid())),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_FALSE(probe_run_directory_lock(dir).held) << "released with the lock";
  EXPECT_NO_THROW(RunDirectoryLock again(dir));
}

TEST(RunDirectoryLock, AnUncreatableDirectoryNamesTheReason) {
  const std::string dir = fresh_dir("uncreatable");
  write(dir + "/file", "");
  try {
    const RunDirectoryLock lock(dir + "/file/out");
    ADD_FAILURE() << "locked a directory below a file";
  } catch (const RunDirectoryError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot create the run directory"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("Not a directory"), std::string::npos) << e.what();
  }
}

TEST(ClaimRunDirectory, AnEarlierRunIsRefusedOrRemovedWithOverwrite) {
  const std::string dir = fresh_dir("claim");
  EXPECT_NO_THROW(claim_run_directory(dir, false));  // empty: fine (and the lock file is no run)
  write(dir + "/run.json", "{}");
  write(dir + "/water.h5", "");
  fs::create_directories(dir + "/checkpoint");
  EXPECT_EQ(earlier_run_outputs(dir), (std::vector<std::string>{"run.json", "water.h5"}));
  write(dir + "/checkpoint/latest.json", "{}");
  write(dir + "/scene.toml", "kept");
  EXPECT_THROW(claim_run_directory(dir, false), RunDirectoryError);
  EXPECT_TRUE(fs::exists(dir + "/run.json"));
  EXPECT_NO_THROW(claim_run_directory(dir, true));
  EXPECT_TRUE(earlier_run_outputs(dir).empty());
  EXPECT_FALSE(fs::exists(dir + "/checkpoint"));
  EXPECT_TRUE(fs::exists(dir + "/scene.toml")) << "only the run's outputs go";
}

TEST(CheckpointScene, ACheckpointOfAnotherSceneIsRefused) {
  const std::string dir = fresh_dir("scene-check");
  CheckpointManifest manifest;
  manifest.coupler_file = dir + "/checkpoint/coupler_0001.json";
  const std::string hash = scene_hash("[scene]\nname = \"a\"\n");
  EXPECT_EQ(hash.size(), 16u);
  EXPECT_NE(hash, scene_hash("[scene]\nname = \"b\"\n"));
  EXPECT_NO_THROW(check_checkpoint_scene(dir, manifest, hash));  // nothing to compare with
  manifest.scene_hash = hash;
  write(dir + "/run.json", R"({"scene": {"name": "a", "hash": ")" + hash + R"("}})");
  EXPECT_NO_THROW(check_checkpoint_scene(dir, manifest, hash));
  write(dir + "/run.json", R"({"scene": {"name": "b", "hash": "0123456789abcdef"}})");
  try {
    check_checkpoint_scene(dir, manifest, hash);
    ADD_FAILURE() << "a checkpoint of another scene than run.json's was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("'b', hash 0123456789abcdef"), std::string::npos)
        << e.what();
  }
  manifest.scene_hash = "0123456789abcdef";
  EXPECT_THROW(check_checkpoint_scene(dir, manifest, hash), std::runtime_error);
}

TEST(RunStatus, ReadsTheRecordAndTheLock) {
  const std::string dir = fresh_dir("status");
  EXPECT_EQ(run_status(dir).code, kStatusNoRun);
  write(dir + "/run.json", R"({"status": "completed", "steps": 20, "simulated_time": 0.02,
                              "end_time": 0.02})");
  EXPECT_EQ(run_status(dir).code, kStatusCompleted);
  write(dir + "/run.json", R"({"status": "failed", "message": "the water solver failed"})");
  const RunStatusReport failed = run_status(dir);
  EXPECT_EQ(failed.code, kStatusFailed);
  EXPECT_NE(failed.text.find("the water solver failed"), std::string::npos) << failed.text;
  write(dir + "/run.json", R"({"status": "running", "coupler": {"pid": 1, "host": "h",
                              "heartbeat_utc": "2026-01-01T00:00:00Z"}})");
  const RunStatusReport died = run_status(dir);
  EXPECT_EQ(died.code, kStatusDied) << died.text;
  EXPECT_NE(died.text.find("coupler pid 1 on host h; heartbeat 2026-01-01T00:00:00Z ("),
            std::string::npos)
      << died.text;
  const RunDirectoryLock lock(dir);
  EXPECT_EQ(run_status(dir).code, kStatusRunning) << run_status(dir).text;
  write(dir + "/run.json", "{ half");
  EXPECT_EQ(run_status(dir).code, kStatusRunning) << "a live run is running whatever run.json says";
}

}  // namespace
}  // namespace porosph::coupler
