#include "common/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace relight {

namespace {

constexpr std::size_t kErrorTailBytes = std::size_t{64} << 10;

// A pipe whose ends close with it; both ends close on exec, so that a program started
// meanwhile on another thread does not hold them open.
struct Pipe {
  std::array<int, 2> fd{-1, -1};
  Pipe() {
    if (pipe2(fd.data(), O_CLOEXEC) != 0)
      throw std::runtime_error(std::string("cannot create a pipe: ") + std::strerror(errno));
  }
  ~Pipe() {
    close_read();
    close_write();
  }
  Pipe(const Pipe&) = delete;
  Pipe& operator=(const Pipe&) = delete;
  void close_read() {
    if (fd[0] >= 0) ::close(fd[0]);
    fd[0] = -1;
  }
  void close_write() {
    if (fd[1] >= 0) ::close(fd[1]);
    fd[1] = -1;
  }
};

struct SpawnActions {
  posix_spawn_file_actions_t actions{};
  SpawnActions() { posix_spawn_file_actions_init(&actions); }
  ~SpawnActions() { posix_spawn_file_actions_destroy(&actions); }
  SpawnActions(const SpawnActions&) = delete;
  SpawnActions& operator=(const SpawnActions&) = delete;
};

int wait_for(pid_t pid) {
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

// Hands every complete line of `pending` to `on_line` and keeps the incomplete rest.
void split_lines(std::string& pending, const ChildOptions& options) {
  std::size_t start = 0;
  for (std::size_t end = pending.find('\n'); end != std::string::npos;
       end = pending.find('\n', start)) {
    if (options.on_error_line) options.on_error_line(pending.substr(start, end - start));
    start = end + 1;
  }
  pending.erase(0, start);
}

}  // namespace

ChildResult run_child(const std::vector<std::string>& argv, const ChildOptions& options) {
  if (argv.empty()) throw std::runtime_error("cannot run a program without a name");
  Pipe out, err;
  SpawnActions spawn;
  posix_spawn_file_actions_addopen(&spawn.actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&spawn.actions, out.fd[1], 1);
  posix_spawn_file_actions_adddup2(&spawn.actions, err.fd[1], 2);
  std::vector<std::string> args = argv;
  std::vector<char*> pointers;
  pointers.reserve(args.size() + 1);
  for (std::string& a : args) pointers.push_back(a.data());
  pointers.push_back(nullptr);
  pid_t pid = 0;
  const int spawned =
      posix_spawnp(&pid, args[0].c_str(), &spawn.actions, nullptr, pointers.data(), environ);
  if (spawned != 0)
    throw std::runtime_error("cannot run " + argv[0] + ": " + std::strerror(spawned));
  out.close_write();
  err.close_write();

  ChildResult result;
  std::string pending;
  std::array<char, 16384> buffer{};
  bool terminated = false;
  std::array<pollfd, 2> fds{pollfd{out.fd[0], POLLIN, 0}, pollfd{err.fd[0], POLLIN, 0}};
  while (fds[0].fd >= 0 || fds[1].fd >= 0) {
    if (!terminated && options.cancelled && options.cancelled()) {
      ::kill(pid, SIGTERM);
      terminated = true;
    }
    const int ready = ::poll(fds.data(), fds.size(), 200);
    if (ready < 0 && errno != EINTR) break;
    for (std::size_t k = 0; k < fds.size(); ++k) {
      if (fds[k].fd < 0 || fds[k].revents == 0) continue;
      const ssize_t n = ::read(fds[k].fd, buffer.data(), buffer.size());
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        fds[k].fd = -1;  // end of file (the pipe itself closes with its Pipe)
        continue;
      }
      const std::string_view bytes(buffer.data(), static_cast<std::size_t>(n));
      if (k == 0) {
        result.out.append(bytes);
        continue;
      }
      result.err_end.append(bytes);
      if (result.err_end.size() > 2 * kErrorTailBytes)
        result.err_end.erase(0, result.err_end.size() - kErrorTailBytes);
      pending.append(bytes);
      split_lines(pending, options);
    }
  }
  if (!pending.empty() && options.on_error_line) options.on_error_line(pending);
  if (result.err_end.size() > kErrorTailBytes)
    result.err_end.erase(0, result.err_end.size() - kErrorTailBytes);
  result.status = wait_for(pid);
  return result;
}

std::string last_line(const std::string& text) {
  const std::size_t end = text.find_last_not_of("\r\n \t");
  if (end == std::string::npos) return "";
  const std::size_t newline = text.rfind('\n', end);
  const std::size_t begin = newline == std::string::npos ? 0 : newline + 1;
  const std::size_t first = text.find_first_not_of(" \t\r", begin);
  return text.substr(first, end + 1 - first);
}

}  // namespace relight
