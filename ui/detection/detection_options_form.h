// SPDX-License-Identifier: MIT
#pragma once

#include <QString>
#include <QWidget>
#include <map>
#include <string>

#include "pipeline/detector.h"

namespace layermod::ui {

// Every detector setting, built from the one field table (VisitDetectorOptions in
// pipeline/detector_options.h): one box per field, grouped by the field's group, each group
// folding open on a click ("matching" starts open). The same table names the QSettings keys
// ("detection/<key>") and the JSON detector profiles, so the CLI's flags, the profiles and this
// form always list the same knobs.
class DetectionOptionsForm : public QWidget {
  Q_OBJECT

 public:
  explicit DetectionOptionsForm(QWidget* parent = nullptr);

  DetectorOptions options() const;
  void SetOptions(const DetectorOptions& options);
  void SaveSettings() const;  // QSettings "detection/…": the fields that differ from the defaults
  void RestoreSettings();
  // Detector profiles (JSON, as `layermod detect --detector-profile`); an error box names the
  // file when it cannot be read or written.
  bool SaveProfile(const QString& path);
  bool LoadProfile(const QString& path);
  // The box of field `key` ("edge_upper"), for tests.
  QWidget* field_widget(const std::string& key) const;

 public slots:
  void SaveProfileDialog();  // "Save detection settings…"
  void LoadProfileDialog();

 private:
  QWidget* AddGroup(const QString& title, bool open);

  std::map<std::string, QWidget*, std::less<>> widgets_;
};

}  // namespace layermod::ui
