#include "coupler/run_directory.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <iterator>
#include <thread>

#include "coupler/phase_slots.h"

namespace porosph::coupler {

namespace {

namespace fs = std::filesystem;

std::string lock_path(const std::string& dir) { return (fs::path(dir) / kLockFileName).string(); }

/// The text of an open lock file (its first line), "" if empty or unreadable.
std::string read_owner(int fd) {
  char buffer[256] = {};
  const ssize_t n = ::pread(fd, buffer, sizeof buffer - 1, 0);
  if (n <= 0) return "";
  std::string text(buffer, static_cast<std::size_t>(n));
  const auto end = text.find('\n');
  return end == std::string::npos ? text : text.substr(0, end);
}

/// "coupler pid 1234 on host node7" from "1234 node7".
std::string describe_owner(const std::string& owner) {
  if (owner.empty()) return "another coupler";
  const auto space = owner.find(' ');
  if (space == std::string::npos) return "coupler pid " + owner;
  return "coupler pid " + owner.substr(0, space) + " on host " + owner.substr(space + 1);
}

/// What marks an earlier run in a directory (README.md "The run directory"), besides each phase's
/// snapshot file under its current and former name (coupler/phase_slots.h). A checkpoint/ without
/// a manifest holds no usable checkpoint: a new run replaces its files before naming them.
constexpr const char* kRunRecordFiles[] = {"run.json", "timeseries.csv", "run.xdmf"};
constexpr const char* kCheckpointManifest = "checkpoint/latest.json";

}  // namespace

RunDirectoryLock::RunDirectoryLock(const std::string& dir) {
  std::error_code error;
  fs::create_directories(dir, error);
  if (error) {
    throw RunDirectoryError("cannot create the run directory '" + dir + "': " + error.message());
  }
  const std::string path = lock_path(dir);
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw RunDirectoryError("cannot write to the run directory '" + dir + "': cannot create " +
                            path + ": " + std::strerror(errno));
  }
  // A `coupler status` holds the lock shared for an instant: retry briefly before refusing.
  int result = -1;
  for (int attempt = 0; attempt < 10; ++attempt) {
    result = ::flock(fd_, LOCK_EX | LOCK_NB);
    if (result == 0 || errno != EWOULDBLOCK) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
  }
  if (result != 0) {
    const int lock_error = errno;
    const std::string owner = read_owner(fd_);
    ::close(fd_);
    fd_ = -1;
    if (lock_error == EWOULDBLOCK) {
      throw RunDirectoryError("the run directory '" + dir +
                              "' is in use: " + describe_owner(owner) + " holds " + path +
                              "; wait for that run to end or choose another --out");
    }
    throw RunDirectoryError("cannot lock " + path + ": " + std::strerror(lock_error));
  }
  const std::string owner = std::to_string(::getpid()) + " " + host_name() + "\n";
  if (::ftruncate(fd_, 0) != 0 ||
      ::pwrite(fd_, owner.data(), owner.size(), 0) != static_cast<ssize_t>(owner.size())) {
    const int write_error = errno;
    ::close(fd_);
    fd_ = -1;
    throw RunDirectoryError("cannot write to the run directory '" + dir + "': cannot write " +
                            path + ": " + std::strerror(write_error));
  }
}

RunDirectoryLock::~RunDirectoryLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock; the file stays (unlinking it would race)
}

LockProbe probe_run_directory_lock(const std::string& dir) {
  LockProbe probe;
  const int fd = ::open(lock_path(dir).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return probe;
  probe.exists = true;
  probe.owner = read_owner(fd);
  if (::flock(fd, LOCK_SH | LOCK_NB) != 0) {
    probe.held = errno == EWOULDBLOCK;
  } else {
    ::flock(fd, LOCK_UN);
  }
  ::close(fd);
  return probe;
}

std::vector<std::string> earlier_run_outputs(const std::string& dir) {
  std::vector<const char*> names(std::begin(kRunRecordFiles), std::end(kRunRecordFiles));
  for (const PhaseSlot& slot : kPhaseSlots) {
    names.push_back(slot.snapshot_file);
    if (slot.former_snapshot_file != nullptr) names.push_back(slot.former_snapshot_file);
  }
  names.push_back(kCheckpointManifest);
  std::vector<std::string> found;
  for (const char* name : names) {
    std::error_code error;
    if (fs::exists(fs::symlink_status(fs::path(dir) / name, error))) found.emplace_back(name);
  }
  return found;
}

void rename_former_snapshot_files(const std::string& dir) {
  for (const PhaseSlot& slot : kPhaseSlots) {
    if (slot.former_snapshot_file == nullptr) continue;
    const fs::path former = fs::path(dir) / slot.former_snapshot_file;
    const fs::path current = fs::path(dir) / slot.snapshot_file;
    std::error_code error;
    if (!fs::exists(former, error) || fs::exists(current, error)) continue;
    fs::rename(former, current, error);
    if (error) {
      throw RunDirectoryError("cannot rename " + former.string() + " to " + current.string() +
                              ": " + error.message());
    }
    std::fprintf(stderr, "coupler: renamed %s to %s (the %s phase's snapshot file is now %s)\n",
                 slot.former_snapshot_file, slot.snapshot_file, slot.phase, slot.snapshot_file);
  }
}

void remove_earlier_run(const std::string& dir) {
  std::vector<std::string> names = earlier_run_outputs(dir);
  std::error_code ignored;
  if (fs::exists(fs::path(dir) / "checkpoint", ignored)) names.emplace_back("checkpoint");
  for (const std::string& name : names) {
    const fs::path path = fs::path(dir) / name;
    std::error_code error;
    fs::remove_all(path, error);
    if (error) {
      throw RunDirectoryError("--overwrite: cannot remove " + path.string() + ": " +
                              error.message());
    }
  }
}

std::unique_ptr<RunDirectoryLock> claim_run_directory(const std::string& dir, bool overwrite) {
  auto lock = std::make_unique<RunDirectoryLock>(dir);  // creates it; refuses a busy one
  const std::vector<std::string> earlier = earlier_run_outputs(dir);
  if (earlier.empty()) return lock;
  if (!overwrite) {
    std::string names;
    for (const std::string& name : earlier) names += (names.empty() ? "" : ", ") + name;
    throw RunDirectoryError("the run directory '" + dir + "' holds an earlier run (" + names +
                            "): give --overwrite to replace it, or choose another --out "
                            "(coupler run --resume " +
                            dir + " continues it from its checkpoint, if it has one)");
  }
  remove_earlier_run(dir);  // its checkpoint too: never resume into another run
  return lock;
}

std::string host_name() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0) return "";
  return name;
}

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  ::gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string scene_hash(const std::string& resolved_toml) {
  std::uint64_t hash = 14695981039346656037ull;
  for (const unsigned char c : resolved_toml) {
    hash ^= c;
    hash *= 1099511628211ull;
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace porosph::coupler
