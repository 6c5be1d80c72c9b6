// SPDX-License-Identifier: MIT
#include "util/log.h"

#include <iostream>
#include <mutex>

namespace layermod {
namespace {

std::mutex& SinkMutex() {
  static std::mutex mutex;
  return mutex;
}

void DefaultSink(LogLevel level, std::string_view message) {
  if (level == LogLevel::kDebug) return;
  std::cerr << LogLevelName(level) << ": " << message << '\n';
}

LogSink& CurrentSink() {
  static LogSink sink = DefaultSink;
  return sink;
}

}  // namespace

LogSink SetLogSink(LogSink sink) {
  std::lock_guard lock(SinkMutex());
  LogSink previous = std::move(CurrentSink());
  CurrentSink() = sink ? std::move(sink) : LogSink(DefaultSink);
  return previous;
}

void Log(LogLevel level, std::string_view message) {
  std::lock_guard lock(SinkMutex());
  CurrentSink()(level, message);
}

std::string_view LogLevelName(LogLevel level) {
  switch (level) {
    case LogLevel::kDebug:
      return "debug";
    case LogLevel::kInfo:
      return "info";
    case LogLevel::kWarning:
      return "warning";
    case LogLevel::kError:
      return "error";
  }
  return "?";
}

}  // namespace layermod
