// SPDX-License-Identifier: MIT
#include "cli/cli_runner.h"

#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <csignal>
#include <stdexcept>

namespace layermod::test {

CliProcess::CliProcess(const std::vector<std::string>& args) {
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) throw std::runtime_error("pipe failed");
  pid_ = ::fork();
  if (pid_ < 0) throw std::runtime_error("fork failed");
  if (pid_ == 0) {
    ::dup2(pipe_fds[1], STDOUT_FILENO);
    ::dup2(pipe_fds[1], STDERR_FILENO);
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    std::vector<char*> argv;
    std::string binary = LAYERMOD_CLI;
    argv.push_back(binary.data());
    std::vector<std::string> copies = args;
    for (std::string& arg : copies) argv.push_back(arg.data());
    argv.push_back(nullptr);
    ::execv(binary.c_str(), argv.data());
    ::_exit(127);
  }
  ::close(pipe_fds[1]);
  fd_ = pipe_fds[0];
}

CliProcess::~CliProcess() {
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    Wait();
  }
}

bool CliProcess::WaitForOutput(const std::string& text) {
  std::array<char, 4096> buffer;
  while (output_.find(text) == std::string::npos) {
    const ssize_t count = ::read(fd_, buffer.data(), buffer.size());
    if (count <= 0) return false;
    output_.append(buffer.data(), static_cast<std::size_t>(count));
  }
  return true;
}

void CliProcess::Signal(int signal_number) { ::kill(pid_, signal_number); }

CliResult CliProcess::Wait() {
  CliResult result;
  if (fd_ >= 0) {
    WaitForOutput(std::string(1, '\0'));  // read to end of output
    ::close(fd_);
    fd_ = -1;
  }
  int status = 0;
  if (pid_ > 0) ::waitpid(pid_, &status, 0);
  pid_ = -1;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.output = output_;
  return result;
}

CliResult RunCli(const std::vector<std::string>& args) { return CliProcess(args).Wait(); }

std::vector<std::string> SplitArgs(const std::string& line) {
  std::vector<std::string> args;
  std::string current;
  bool quoted = false;
  bool has_token = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
      has_token = true;
    } else if (c == ' ' && !quoted) {
      if (has_token) args.push_back(current);
      current.clear();
      has_token = false;
    } else {
      current.push_back(c);
      has_token = true;
    }
  }
  if (has_token) args.push_back(current);
  return args;
}

}  // namespace layermod::test
