// SPDX-License-Identifier: MIT
#pragma once

#include <QDockWidget>

#include "util/log.h"

class QPlainTextEdit;

namespace layermod::ui {

// Shows the core's log. While it lives it is the process-wide log sink: messages from any thread
// arrive here through a queued call.
class LogDock : public QDockWidget {
  Q_OBJECT

 public:
  explicit LogDock(QWidget* parent = nullptr);
  ~LogDock() override;  // gives the log back to the previous sink

  QString Text() const;

 public slots:
  void Append(int level, const QString& message);

 private:
  QPlainTextEdit* text_ = nullptr;
  LogSink previous_sink_;
};

}  // namespace layermod::ui
