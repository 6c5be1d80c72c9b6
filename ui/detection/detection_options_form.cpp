// SPDX-License-Identifier: MIT
#include "ui/detection/detection_options_form.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QStringList>
#include <QToolButton>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <exception>
#include <type_traits>

#include "pipeline/detector_options.h"
#include "ui/common/studio_dialogs.h"
#include "ui/widgets/fold_header.h"

namespace layermod::ui {
namespace {

constexpr char kOpenGroup[] = "matching";

QString Text(std::string_view text) {
  return QString::fromUtf8(text.data(), static_cast<int>(text.size()));
}

// "edge_upper" -> "detectionEdgeUpper" (the boxes' object names).
QString ObjectName(std::string_view key) {
  QString name = QStringLiteral("detection");
  bool upper = true;
  for (char c : key) {
    if (c == '_') {
      upper = true;
      continue;
    }
    name += upper ? QChar(c).toUpper() : QChar(c);
    upper = false;
  }
  return name;
}

// "min_inlier_ratio" -> "Min inlier ratio", "nms_radius" -> "NMS radius", "icp_max_step_deg" ->
// "ICP max step (deg)": the key's words, acronyms in capitals and a trailing unit in brackets.
QString Label(std::string_view key) {
  QStringList words = Text(key).split('_', Qt::SkipEmptyParts);
  for (QString& word : words) {
    if (word == "nms" || word == "icp") word = word.toUpper();
  }
  if (words.size() > 1 && words.back() == "deg") words.back() = "(deg)";
  QString label = words.join(' ');
  if (!label.isEmpty()) label[0] = label[0].toUpper();
  return label;
}

// Enough decimals to show `value` exactly (a default of 0.005 must not round to 0.01): the
// fewest whose rounded value, read back into T as ReadBox does, is the default again (a float
// default of 0.15 shows as 0.150, not as the 0.150000006 of its double).
template <typename T>
int DecimalsFor(T value, double max) {
  for (int decimals = max <= 1.0 ? 3 : 1; decimals < 6; ++decimals) {
    const double scale = std::pow(10.0, decimals);
    if (static_cast<T>(std::round(static_cast<double>(value) * scale) / scale) == value) {
      return decimals;
    }
  }
  return 6;
}

template <typename T>
QWidget* MakeBox(const DetectorOptionField& field, const T& default_value) {
  if constexpr (kIsChoiceOption<T>) {
    auto* box = new QComboBox;
    for (T choice : OptionChoices<T>::kValues) box->addItem(Text(OptionChoices<T>::Name(choice)));
    return box;
  } else if constexpr (std::is_integral_v<T>) {
    auto* box = new QSpinBox;
    box->setRange(static_cast<int>(field.min), static_cast<int>(field.max));
    if (field.max >= 10000) box->setSingleStep(100);
    return box;
  } else {
    auto* box = new QDoubleSpinBox;
    box->setDecimals(DecimalsFor(default_value, field.max));
    box->setRange(field.min, field.max);
    box->setSingleStep(field.max <= 1.0 ? 0.05 : field.max <= 10.0 ? 0.1 : 1.0);
    return box;
  }
}

template <typename T>
void ReadBox(const QWidget* widget, T& value) {
  if constexpr (kIsChoiceOption<T>) {
    value = OptionChoices<T>::kValues[std::max(
        0, static_cast<const QComboBox*>(widget)->currentIndex())];
  } else if constexpr (std::is_integral_v<T>) {
    value = static_cast<T>(static_cast<const QSpinBox*>(widget)->value());
  } else {
    value = static_cast<T>(static_cast<const QDoubleSpinBox*>(widget)->value());
  }
}

template <typename T>
void WriteBox(QWidget* widget, const T& value) {
  if constexpr (kIsChoiceOption<T>) {
    const auto& choices = OptionChoices<T>::kValues;
    for (int i = 0; i < static_cast<int>(choices.size()); ++i) {
      if (choices[i] == value) static_cast<QComboBox*>(widget)->setCurrentIndex(i);
    }
  } else if constexpr (std::is_integral_v<T>) {
    static_cast<QSpinBox*>(widget)->setValue(static_cast<int>(value));
  } else {
    static_cast<QDoubleSpinBox*>(widget)->setValue(static_cast<double>(value));
  }
}

}  // namespace

DetectionOptionsForm::DetectionOptionsForm(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(2);
  std::map<std::string, QFormLayout*, std::less<>> groups;
  const DetectorOptions defaults;
  DetectorOptions fields = defaults;
  VisitDetectorOptions(fields, [&](const DetectorOptionField& field, auto& value) {
    auto group = groups.find(field.group);
    if (group == groups.end()) {
      QWidget* body = AddGroup(Text(field.group), field.group == kOpenGroup);
      group = groups.emplace(std::string(field.group), new QFormLayout(body)).first;
      group->second->setContentsMargins(12, 0, 0, 4);
    }
    QWidget* box = MakeBox(field, value);
    box->setObjectName(ObjectName(field.key));
    box->setToolTip(Text(field.help));
    group->second->addRow(Label(field.key), box);
    widgets_.emplace(std::string(field.key), box);
  });
  auto* save = new QPushButton(tr("Save settings…"));
  auto* load = new QPushButton(tr("Load settings…"));
  save->setToolTip(
      tr("Save detection settings (a detector profile, as `layermod detect "
         "--detector-profile` reads)"));
  load->setToolTip(tr("Load detection settings from a detector profile"));
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(load);
  buttons->addWidget(save);
  layout->addLayout(buttons);
  connect(save, &QPushButton::clicked, this, &DetectionOptionsForm::SaveProfileDialog);
  connect(load, &QPushButton::clicked, this, &DetectionOptionsForm::LoadProfileDialog);
  SetOptions(defaults);
}

QWidget* DetectionOptionsForm::AddGroup(const QString& title, bool open) {
  auto* body = new QWidget;
  QToolButton* header = MakeFoldHeader(body, open);
  header->setText(title.left(1).toUpper() + title.mid(1));
  header->setObjectName(QStringLiteral("group_") + QString(title).replace(' ', '_'));
  layout()->addWidget(header);
  layout()->addWidget(body);
  return body;
}

QWidget* DetectionOptionsForm::field_widget(const std::string& key) const {
  const auto found = widgets_.find(key);
  return found == widgets_.end() ? nullptr : found->second;
}

DetectorOptions DetectionOptionsForm::options() const {
  DetectorOptions options;
  VisitDetectorOptions(options, [this](const DetectorOptionField& field, auto& value) {
    ReadBox(widgets_.find(field.key)->second, value);
  });
  return options;
}

void DetectionOptionsForm::SetOptions(const DetectorOptions& options) {
  DetectorOptions copy = options;
  VisitDetectorOptions(copy, [this](const DetectorOptionField& field, auto& value) {
    WriteBox(widgets_.find(field.key)->second, value);
  });
}

void DetectionOptionsForm::SaveSettings() const {
  // Only what differs from the defaults: a field the user never changed follows the defaults of
  // a later studio (as occlusion-aware matching became one).
  QSettings settings;
  const nlohmann::json json = DetectorOptionsToJson(options());
  const nlohmann::json defaults = DetectorOptionsToJson(DetectorOptions{});
  for (const auto& [key, value] : json.items()) {
    const QString settings_key = QStringLiteral("detection/") + QString::fromStdString(key);
    if (defaults.contains(key) && defaults.at(key) == value) {
      settings.remove(settings_key);
    } else {
      settings.setValue(settings_key, QString::fromStdString(value.dump()));
    }
  }
}

void DetectionOptionsForm::RestoreSettings() {
  const QSettings settings;
  DetectorOptions options;
  for (const DetectorOptionField& field : DetectorOptionFields()) {
    const QString key = QStringLiteral("detection/") + Text(field.key);
    if (!settings.contains(key)) continue;  // saved before the field existed: the default
    // Field by field, so that one value of an older studio (e.g. the mode saved as a list
    // index) or out of today's range keeps its default without losing the others.
    try {
      nlohmann::json json = nlohmann::json::object();
      json[std::string(field.key)] =
          nlohmann::json::parse(settings.value(key).toString().toStdString());
      options = DetectorOptionsFromJson(json, "saved detection settings", options);
    } catch (const std::exception&) {
    }
  }
  SetOptions(options);
}

void DetectionOptionsForm::SaveProfileDialog() {
  const QString path = AskSavePath(this, "detector", tr("Save detection settings"),
                                   JsonFileFilter(), "detector.json");
  if (!path.isEmpty()) SaveProfile(path);
}

void DetectionOptionsForm::LoadProfileDialog() {
  const QString path =
      AskOpenPath(this, "detector", tr("Load detection settings"), JsonFileFilter());
  if (!path.isEmpty()) LoadProfile(path);
}

bool DetectionOptionsForm::SaveProfile(const QString& path) {
  try {
    WriteDetectorProfile(path.toStdString(), options());
    return true;
  } catch (const std::exception& error) {
    ShowError(this, tr("Save detection settings “%1”").arg(path),
              QString::fromStdString(error.what()));
    return false;
  }
}

bool DetectionOptionsForm::LoadProfile(const QString& path) {
  try {
    SetOptions(ReadDetectorProfile(path.toStdString()));
    return true;
  } catch (const std::exception& error) {
    ShowError(this, tr("Load detection settings “%1”").arg(path),
              QString::fromStdString(error.what()));
    return false;
  }
}

}  // namespace layermod::ui
