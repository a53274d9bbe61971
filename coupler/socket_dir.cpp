#include "coupler/socket_dir.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

namespace porosph::coupler {
namespace {

namespace fs = std::filesystem;

constexpr const char* kPrefix = "porosph-";
constexpr const char* kLockName = "lock";
constexpr const char* kSocketName = "coupler.ipc";

/// $TMPDIR, else /tmp; /tmp when the socket path would not fit a sockaddr_un.
std::string default_base() {
  const char* tmpdir = std::getenv("TMPDIR");
  std::string base = tmpdir != nullptr && *tmpdir != '\0' ? tmpdir : "/tmp";
  // <base>/porosph-<pid>-XXXXXX/coupler.ipc
  const std::size_t needed = base.size() + 1 + 8 + 10 + 1 + 6 + 1 + 11 + 1;
  if (needed > sizeof(sockaddr_un{}.sun_path)) base = "/tmp";
  return base;
}

/// True when `dir` is a directory of this user with a lock file that nobody holds; then removes
/// it (still holding the lock while it does).
bool remove_if_stale(const std::string& dir) {
  struct stat info {};
  if (::lstat(dir.c_str(), &info) != 0 || !S_ISDIR(info.st_mode) || info.st_uid != ::geteuid()) {
    return false;
  }
  const std::string lock = dir + "/" + kLockName;
  const int fd = ::open(lock.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return false;  // not ours, or being created (the lock file comes last)
  bool removed = false;
  if (::flock(fd, LOCK_EX | LOCK_NB) == 0) {
    std::error_code error;
    removed = fs::remove_all(dir, error) > 0 && !error;
  }
  ::close(fd);
  return removed;
}

}  // namespace

int sweep_stale_socket_dirs(const std::string& base) {
  DIR* listing = ::opendir(base.c_str());
  if (listing == nullptr) return 0;
  std::vector<std::string> candidates;
  while (const dirent* entry = ::readdir(listing)) {
    if (std::strncmp(entry->d_name, kPrefix, std::strlen(kPrefix)) == 0) {
      candidates.push_back(base + "/" + entry->d_name);
    }
  }
  ::closedir(listing);
  int removed = 0;
  for (const std::string& dir : candidates) removed += remove_if_stale(dir) ? 1 : 0;
  return removed;
}

PrivateSocketDir::PrivateSocketDir(const std::string& base_arg) {
  const std::string base = base_arg.empty() ? default_base() : base_arg;
  sweep_stale_socket_dirs(base);
  std::string pattern = base + "/" + kPrefix + std::to_string(::getpid()) + "-XXXXXX";
  if (::mkdtemp(pattern.data()) == nullptr) {  // mode 0700 whatever the umask
    throw std::runtime_error("cannot create a private directory for the solver socket in " + base +
                             ": " + std::strerror(errno));
  }
  path_ = pattern;
  // Lock first, then give the lock file its name: a sweeping coupler never sees it unlocked.
  const std::string creating = path_ + "/" + kLockName + ".new";
  lock_fd_ = ::open(creating.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (lock_fd_ < 0 || ::flock(lock_fd_, LOCK_EX) != 0 ||
      ::rename(creating.c_str(), (path_ + "/" + kLockName).c_str()) != 0) {
    const int error_number = errno;
    std::error_code ignored;
    fs::remove_all(path_, ignored);
    if (lock_fd_ >= 0) ::close(lock_fd_);
    throw std::runtime_error("cannot lock the solver socket directory " + path_ + ": " +
                             std::strerror(error_number));
  }
}

PrivateSocketDir::~PrivateSocketDir() {
  std::error_code ignored;
  fs::remove_all(path_, ignored);
  if (lock_fd_ >= 0) ::close(lock_fd_);
}

std::string PrivateSocketDir::endpoint() const { return "ipc://" + path_ + "/" + kSocketName; }

}  // namespace porosph::coupler
