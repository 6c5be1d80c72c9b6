// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace layermod {

enum class LogLevel { kDebug, kInfo, kWarning, kError };

// The core never prints: it logs through this facade. The CLI sends messages to stderr, the GUI
// to its log dock. The default sink drops debug messages and writes the rest to stderr.
using LogSink = std::function<void(LogLevel, std::string_view message)>;

// Replaces the process-wide sink; returns the previous one. Thread-safe.
LogSink SetLogSink(LogSink sink);
void Log(LogLevel level, std::string_view message);

inline void LogDebug(std::string_view message) { Log(LogLevel::kDebug, message); }
inline void LogInfo(std::string_view message) { Log(LogLevel::kInfo, message); }
inline void LogWarning(std::string_view message) { Log(LogLevel::kWarning, message); }
inline void LogError(std::string_view message) { Log(LogLevel::kError, message); }

std::string_view LogLevelName(LogLevel level);

}  // namespace layermod
