// SPDX-License-Identifier: MIT
#include "ui/window/log_dock.h"

#include <QPlainTextEdit>
#include <QTime>

namespace layermod::ui {
namespace {

constexpr int kMaxLogLines = 5000;

}  // namespace

LogDock::LogDock(QWidget* parent) : QDockWidget(tr("Log"), parent), text_(new QPlainTextEdit) {
  setObjectName("LogDock");
  text_->setReadOnly(true);
  text_->setMaximumBlockCount(kMaxLogLines);
  text_->setLineWrapMode(QPlainTextEdit::NoWrap);
  setWidget(text_);
  previous_sink_ = SetLogSink([this](LogLevel level, std::string_view message) {
    const QString text = QString::fromUtf8(message.data(), static_cast<int>(message.size()));
    const int level_value = static_cast<int>(level);
    QMetaObject::invokeMethod(
        this, [this, level_value, text] { Append(level_value, text); }, Qt::QueuedConnection);
  });
}

LogDock::~LogDock() {
  // Log() holds the sink lock while it calls the sink, so after this no call can reach `this`.
  SetLogSink(std::move(previous_sink_));
}

QString LogDock::Text() const { return text_->toPlainText(); }

void LogDock::Append(int level, const QString& message) {
  const auto log_level = static_cast<LogLevel>(level);
  if (log_level == LogLevel::kDebug) return;
  const std::string_view name_text = LogLevelName(log_level);
  const QString name = QString::fromUtf8(name_text.data(), static_cast<int>(name_text.size()));
  text_->appendPlainText(
      QStringLiteral("%1 %2: %3").arg(QTime::currentTime().toString("HH:mm:ss"), name, message));
}

}  // namespace layermod::ui
