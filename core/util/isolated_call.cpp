// SPDX-License-Identifier: MIT
#include "util/isolated_call.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <new>

#include "util/error.h"

namespace layermod {
namespace {

// First byte of the child's answer.
constexpr char kResult = 'R';
constexpr char kError = 'E';
constexpr char kIoError = 'I';
constexpr char kFormatError = 'F';

void WriteAll(int fd, const std::string& bytes) {
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent stopped listening: nothing left to tell it
    written += static_cast<std::size_t>(n);
  }
}

std::string ChildAnswer(const std::function<std::string()>& work) {
  try {
    return kResult + work();
  } catch (const FormatError& error) {
    return kFormatError + std::string(error.what());
  } catch (const IoError& error) {
    return kIoError + std::string(error.what());
  } catch (const Error& error) {
    return kError + std::string(error.what());
  } catch (const std::bad_alloc&) {
    return kFormatError + std::string("out of memory");
  } catch (const std::exception& error) {
    return kFormatError + std::string(error.what());
  }
}

[[noreturn]] void RunChild(int fd, const std::function<std::string()>& work) {
  // A fault kills the child at once: no handler inherited from the parent (a crash reporter, a
  // sanitizer's or fuzzer's report) runs, and the parent sees the signal.
  for (int signal_number : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) {
    ::signal(signal_number, SIG_DFL);
  }
  WriteAll(fd, ChildAnswer(work));
  ::close(fd);
  ::_exit(0);
}

// Reads the child's answer until end of file or the deadline. False on timeout.
bool ReadAnswer(int fd, std::chrono::steady_clock::time_point deadline, std::string& answer) {
  char buffer[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd poll_fd{fd, POLLIN, 0};
    const int ready = ::poll(&poll_fd, 1, static_cast<int>(left.count()));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) return false;  // deadline passed
    if (ready < 0) return true;    // a broken pipe ends the answer like end of file
    const ssize_t n = ::read(fd, buffer, sizeof(buffer));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    answer.append(buffer, static_cast<std::size_t>(n));
  }
}

int ReapChild(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  return status;
}

std::string Unpack(const std::string& answer, int status, const std::string& failure_prefix) {
  if (WIFSIGNALED(status)) {
    throw FormatError(failure_prefix + " crashed (signal " + std::to_string(WTERMSIG(status)) +
                      ") on this file; it is malformed or uses a variant that cannot be read");
  }
  if (answer.empty()) {
    // A sanitizer or an abort handler may turn a crash into a plain non-zero exit.
    throw FormatError(failure_prefix + " crashed (exit status " +
                      std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                      ") on this file; it is malformed or uses a variant that cannot be read");
  }
  const std::string body = answer.substr(1);
  switch (answer.front()) {
    case kResult:
      return body;
    case kIoError:
      throw IoError(body);
    case kError:
      throw Error(body);
    default:
      throw FormatError(body);
  }
}

}  // namespace

std::string RunIsolated(const std::function<std::string()>& work, std::chrono::seconds timeout,
                        const std::string& failure_prefix) {
  int fds[2];
  if (::pipe(fds) != 0)
    throw Error(failure_prefix + ": cannot create a pipe: " + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw Error(failure_prefix + ": cannot start a process: " + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(fds[0]);
    RunChild(fds[1], work);
  }
  ::close(fds[1]);
  std::string answer;
  const bool finished = ReadAnswer(fds[0], std::chrono::steady_clock::now() + timeout, answer);
  ::close(fds[0]);
  if (!finished) ::kill(pid, SIGKILL);
  const int status = ReapChild(pid);
  if (!finished) {
    throw FormatError(failure_prefix + " took longer than " + std::to_string(timeout.count()) +
                      " s on this file and was stopped; it is malformed or far too large");
  }
  return Unpack(answer, status, failure_prefix);
}

}  // namespace layermod
