// SPDX-License-Identifier: MIT
#include "ui/detection/detection_panel.h"

#include <QCheckBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QSpinBox>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>
#include <algorithm>

#include "pipeline/overlays.h"
#include "ui/common/image_convert.h"
#include "ui/common/job_runner.h"
#include "ui/common/studio_dialogs.h"
#include "ui/common/studio_session.h"
#include "ui/detection/capture_dialog.h"
#include "ui/detection/detection_options_form.h"
#include "ui/detection/detection_table.h"
#include "ui/detection/ground_truth_text.h"
#include "ui/detection/image_view.h"
#include "util/log.h"

namespace layermod::ui {
namespace {

constexpr int kControlsWidthPx = 330;
constexpr int kControlsMinWidthPx = 220;

// One line of swatches per object, wrapping: "bracket: ■ 0: 633  ■ 1: 700 … mm".
QString LegendHtml(const ArchiveObject& object) {
  const int layers = static_cast<int>(object.layer_depths_mm.size());
  QString html = QStringLiteral("<b>%1</b> layers (mm):")
                     .arg(QString::fromStdString(object.name).toHtmlEscaped());
  for (int i = 0; i < layers; ++i) {
    const cv::Scalar bgr = LayerColor(i, layers);
    const QColor colour(static_cast<int>(bgr[2]), static_cast<int>(bgr[1]),
                        static_cast<int>(bgr[0]));
    html += QStringLiteral(" <span style=\"color:%1\">&#9632;</span>&nbsp;%2:&nbsp;%3")
                .arg(colour.name())
                .arg(i)
                .arg(object.layer_depths_mm[static_cast<std::size_t>(i)], 0, 'f', 0);
  }
  return html + QStringLiteral("<br>");
}

}  // namespace

DetectionPanel::DetectionPanel(StudioSession* session, JobRunner* runner, QWidget* parent)
    : QWidget(parent),
      session_(session),
      runner_(runner),
      bop_dir_(new QLineEdit),
      scene_(new QSpinBox),
      frame_(new QSpinBox),
      capture_label_(new QLabel(tr("No capture"))),
      archive_label_(new QLabel),
      coverage_label_(new QLabel),
      options_(new DetectionOptionsForm),
      detect_on_load_(new QCheckBox(tr("Detect on load"))),
      detect_(new QPushButton(tr("Detect"))),
      legend_(new QLabel),
      image_(new ImageView),
      table_(new QTableWidget),
      timings_(new QLabel) {
  auto* splitter = new QSplitter(Qt::Horizontal);
  splitter->setObjectName("detectionSplitter");
  splitter->addWidget(BuildControls());
  splitter->addWidget(BuildResultsArea());
  splitter->setStretchFactor(1, 1);
  splitter->setCollapsible(0, false);
  splitter->setSizes({kControlsWidthPx, 1000});
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(2, 2, 2, 2);
  layout->addWidget(splitter);

  options_->RestoreSettings();
  QSettings settings;
  bop_dir_->setText(settings.value("detection/bop_dir").toString());
  scene_->setValue(settings.value("detection/scene", 1).toInt());
  frame_->setValue(settings.value("detection/frame", 0).toInt());
  detect_on_load_->setChecked(settings.value("detection/detect_on_load", true).toBool());

  connect(detect_, &QPushButton::clicked, this, &DetectionPanel::Detect);
  connect(runner_, &JobRunner::BusyChanged, this, [this](bool busy) {
    if (!busy) RunPending();
    UpdateState();
  });
  connect(session_, &StudioSession::ArchiveChanged, this, &DetectionPanel::OnArchiveChanged);
  UpdateState();
}

DetectionPanel::~DetectionPanel() {
  QSettings settings;
  settings.setValue("detection/detect_on_load", detect_on_load_->isChecked());
  options_->SaveSettings();
}

QWidget* DetectionPanel::BuildControls() {
  auto* controls = new QWidget;
  auto* controls_layout = new QVBoxLayout(controls);
  controls_layout->setContentsMargins(0, 0, 0, 0);
  // Capture and Detect first, so both stay in sight on a short screen; the settings follow.
  controls_layout->addWidget(BuildCaptureBox());
  controls_layout->addWidget(BuildDetectBox());
  controls_layout->addWidget(BuildOverlayBox());
  auto* settings_box = new QGroupBox(tr("Detection settings"));
  (new QVBoxLayout(settings_box))->addWidget(options_);
  controls_layout->addWidget(settings_box);
  controls_layout->addStretch();
  // Scrolls rather than clipping when the window is short.
  auto* scroll = new QScrollArea;
  scroll->setWidget(controls);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  // Never narrower than the controls: a clipped Detect button is worse than a smaller image.
  scroll->setMinimumWidth(std::max(kControlsMinWidthPx, controls->minimumSizeHint().width()) +
                          scroll->verticalScrollBar()->sizeHint().width());
  return scroll;
}

QWidget* DetectionPanel::BuildCaptureBox() {
  auto* box = new QGroupBox(tr("Capture"));
  bop_dir_->setObjectName("bopDir");
  bop_dir_->setPlaceholderText(tr("BOP split folder (holding 000001/ …)"));
  scene_->setObjectName("sceneBox");
  frame_->setObjectName("frameBox");
  scene_->setRange(0, 999999);
  frame_->setRange(0, 999999);
  auto* browse = new QPushButton(tr("Browse…"));
  auto* load = new QPushButton(tr("Load frame"));
  load->setObjectName("loadFrameButton");
  auto* files = new QPushButton(tr("Capture files…"));
  files->setToolTip(tr("Colour image, depth PNG and camera.json in one dialog"));
  load->setToolTip(tr("Enter in the folder, scene or frame box loads too; PgUp/PgDn step frames"));
  capture_label_->setObjectName("captureLabel");
  capture_label_->setWordWrap(true);
  auto* dir_row = new QHBoxLayout;
  dir_row->addWidget(bop_dir_, 1);
  dir_row->addWidget(browse);
  auto* frame_row = new QHBoxLayout;
  frame_row->addWidget(new QLabel(tr("Scene")));
  frame_row->addWidget(scene_);
  frame_row->addWidget(new QLabel(tr("Frame")));
  frame_row->addWidget(frame_);
  auto* load_row = new QHBoxLayout;
  load_row->addWidget(load);
  load_row->addWidget(files);
  auto* layout = new QVBoxLayout(box);
  layout->addLayout(dir_row);
  layout->addLayout(frame_row);
  layout->addLayout(load_row);
  layout->addWidget(capture_label_);
  connect(browse, &QPushButton::clicked, this, &DetectionPanel::OpenBopFrameDialog);
  connect(load, &QPushButton::clicked, this, &DetectionPanel::LoadFrameFromForm);
  connect(bop_dir_, &QLineEdit::returnPressed, this, &DetectionPanel::LoadFrameFromForm);
  // A spin box's Enter reaches its line edit as returnPressed.
  for (QSpinBox* spin : {scene_, frame_}) {
    connect(spin->findChild<QLineEdit*>(), &QLineEdit::returnPressed, this,
            &DetectionPanel::LoadFrameFromForm);
  }
  connect(files, &QPushButton::clicked, this, &DetectionPanel::OpenCaptureFilesDialog);
  return box;
}

QWidget* DetectionPanel::BuildDetectBox() {
  auto* box = new QGroupBox(tr("Detection"));
  archive_label_->setObjectName("detectionArchiveLabel");
  archive_label_->setWordWrap(true);
  auto* open_archive = new QPushButton(tr("Open archive…"));
  detect_->setObjectName("detectButton");
  detect_->setToolTip(tr("Detect the template set's objects in the capture (Ctrl+D)"));
  detect_on_load_->setObjectName("detectOnLoad");
  auto* buttons = new QHBoxLayout;
  buttons->addWidget(open_archive);
  buttons->addWidget(detect_);
  coverage_label_->setObjectName("groundTruthLabel");
  coverage_label_->setWordWrap(true);
  coverage_label_->setToolTip(
      tr("Whether the template set's views, rolls and depth layers reach each ground-truth pose "
         "of the frame: no template matches a pose outside closely, so it is likely missed "
         "(widen the envelope or set the up axis). Its camera is drawn in the 3D view."));
  coverage_label_->hide();
  auto* layout = new QVBoxLayout(box);
  layout->addWidget(archive_label_);
  layout->addWidget(coverage_label_);
  layout->addLayout(buttons);
  layout->addWidget(detect_on_load_);
  connect(open_archive, &QPushButton::clicked, this, &DetectionPanel::OpenArchiveRequested);
  return box;
}

QWidget* DetectionPanel::BuildOverlayBox() {
  auto* box = new QGroupBox(tr("Overlays"));
  auto* layout = new QVBoxLayout(box);
  const QString titles[4] = {tr("Region division (blocks by layer)"),
                             tr("Coarse positioning (kept / rejected)"), tr("Template matches"),
                             tr("Final poses (contour and axes)")};
  const char* names[4] = {"overlayRegions", "overlayCoarse", "overlayMatches", "overlayPoses"};
  for (int i = 0; i < 4; ++i) {
    toggles_[i] = new QCheckBox(titles[i]);
    toggles_[i]->setObjectName(names[i]);
    toggles_[i]->setChecked(i == 3);
    layout->addWidget(toggles_[i]);
    connect(toggles_[i], &QCheckBox::toggled, this, &DetectionPanel::RefreshImage);
  }
  legend_->setObjectName("layerLegend");
  legend_->setTextFormat(Qt::RichText);
  legend_->setWordWrap(true);
  layout->addWidget(legend_);
  return box;
}

QWidget* DetectionPanel::BuildResultsArea() {
  image_->setObjectName("detectionImage");
  table_->setObjectName("detectionTable");
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setSelectionBehavior(QAbstractItemView::SelectRows);
  table_->verticalHeader()->setVisible(false);
  table_->setToolTip(
      tr("Double-click a detection to see it in the 3D view against the capture's "
         "points"));
  connect(table_, &QTableWidget::cellDoubleClicked, this,
          [this](int row) { emit DetectionActivated(row); });
  FillDetectionTable(table_, {});
  timings_->setObjectName("timingsLabel");
  timings_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  // Wraps rather than widening the window: its width would outlast the preview (QTabWidget takes
  // the largest minimum of its pages) and push the docks past a laptop screen.
  timings_->setWordWrap(true);
  auto* lower = new QWidget;
  auto* lower_layout = new QVBoxLayout(lower);
  lower_layout->setContentsMargins(0, 0, 0, 0);
  lower_layout->addWidget(table_);
  lower_layout->addWidget(timings_);
  auto* splitter = new QSplitter(Qt::Vertical);
  splitter->addWidget(image_);
  splitter->addWidget(lower);
  splitter->setStretchFactor(0, 4);
  splitter->setStretchFactor(1, 1);
  return splitter;
}

void DetectionPanel::OpenBopFrameDialog() {
  QString start = bop_dir_->text();
  if (start.isEmpty()) start = QSettings().value("dirs/capture").toString();
  const QString dir =
      QFileDialog::getExistingDirectory(this, tr("BOP split folder (e.g. test/)"), start);
  if (dir.isEmpty()) return;
  bop_dir_->setText(dir);
  OpenCapture({dir, scene_->value(), frame_->value(), {}, {}, {}});
}

void DetectionPanel::OpenCaptureFilesDialog() {
  CaptureDialog dialog(this);
  if (dialog.exec() == QDialog::Accepted) OpenCapture(dialog.source());
}

void DetectionPanel::LoadFrameFromForm() {
  if (bop_dir_->text().isEmpty()) return OpenBopFrameDialog();
  OpenCapture({bop_dir_->text(), scene_->value(), frame_->value(), {}, {}, {}});
}

int DetectionPanel::frame_in_form() const { return frame_->value(); }

bool DetectionPanel::StepFrame(int step) {
  if (!can_step_frames()) return false;
  const int next = NeighbourFrame(frame_ids_, frame_->value(), step);
  if (next < 0) return false;
  // The form shows the target at once, so repeated steps go on from it.
  frame_->setValue(next);
  OpenCapture({source_.bop_dir, source_.scene_id, next, {}, {}, {}});
  return true;
}

bool DetectionPanel::can_detect() const {
  return !runner_->busy() && capture_ != nullptr && session_->archive() != nullptr;
}

void DetectionPanel::OpenBopFolder(const QString& split_dir) {
  OpenCapture({split_dir, scene_->value(), frame_->value(), {}, {}, {}});
}

void DetectionPanel::OpenCapture(const CaptureSource& source) {
  queued_capture_ = source;
  RunWhenFree([this] {
    if (!queued_capture_.has_value()) return false;  // a later request took it already
    const CaptureSource next = *queued_capture_;
    queued_capture_.reset();
    return StartLoad(next);
  });
}

bool DetectionPanel::Detect() {
  if (capture_ == nullptr && pending_.empty()) return false;
  if (session_->archive() == nullptr) return false;
  RunWhenFree([this] { return StartDetect(); });
  return true;
}

void DetectionPanel::RunWhenFree(std::function<bool()> start) {
  pending_.push_back(std::move(start));
  RunPending();
  UpdateState();
}

void DetectionPanel::RunPending() {
  while (!pending_.empty() && !runner_->busy()) {
    const auto start = pending_.front();
    pending_.erase(pending_.begin());
    if (start()) return;
  }
}

bool DetectionPanel::StartLoad(const CaptureSource& source) {
  return runner_->Start(
      tr("Open capture %1").arg(source.Describe()), [this, source](const JobControl&) {
        auto loaded = std::make_shared<LoadedCapture>(LoadCaptureSource(source));
        auto capture = std::make_shared<const Capture>(std::move(loaded->capture));
        return JobRunner::Commit(
            [this, source, capture, loaded] { ShowCapture(source, capture, std::move(*loaded)); });
      });
}

void DetectionPanel::ShowCapture(const CaptureSource& source,
                                 std::shared_ptr<const Capture> capture, LoadedCapture loaded) {
  source_ = source;
  frame_ids_ = std::move(loaded.scene_frame_ids);
  ground_truth_ = std::move(loaded.ground_truth);
  capture_ = std::move(capture);
  result_ = nullptr;
  result_detector_ = nullptr;
  if (source.is_bop()) {
    QSettings settings;
    settings.setValue("detection/bop_dir", source.bop_dir);
    settings.setValue("detection/scene", source.scene_id);
    settings.setValue("detection/frame", source.frame_id);
    bop_dir_->setText(source.bop_dir);
    scene_->setValue(source.scene_id);
    // A step already queued further shows its own target.
    if (!queued_capture_.has_value()) frame_->setValue(source.frame_id);
  } else {
    // The files do not come from the folder: showing it would misname the capture.
    bop_dir_->clear();
  }
  capture_label_->setText(tr("%1<br>%2 × %3 px, %4")
                              .arg(source.Describe().toHtmlEscaped())
                              .arg(capture_->color.cols)
                              .arg(capture_->color.rows)
                              .arg(capture_->depth_mm.empty() ? tr("no depth") : tr("with depth")));
  FillDetectionTable(table_, {});
  timings_->clear();
  RefreshImage();
  UpdateCoverage();
  UpdateState();
  emit CaptureOpened();
  // While frames are stepped through quickly, only the last one is detected.
  if (detect_on_load_->isChecked() && session_->archive() != nullptr &&
      !queued_capture_.has_value()) {
    Detect();
  }
}

bool DetectionPanel::StartDetect() {
  const auto archive = session_->archive();
  const auto capture = capture_;
  if (archive == nullptr || capture == nullptr) return false;
  const DetectorOptions options = options_->options();
  const auto cached = archive == detector_archive_ ? detector_ : nullptr;
  const QString name = tr("Detect in %1 with %2").arg(source_.Describe(), ArchiveText());
  return runner_->Start(name, [=, this](const JobControl& job) {
    options.Validate();
    auto detector = cached;
    if (detector == nullptr) {
      detector = std::make_shared<const Detector>(std::vector<TemplateArchive>{*archive});
    }
    job.ThrowIfCancelled();
    auto result = std::make_shared<const DetectionResult>(detector->Detect(*capture, options));
    return JobRunner::Commit([=, this] {
      detector_archive_ = archive;
      detector_ = detector;
      if (capture == capture_) ShowResult(detector, result);
    });
  });
}

void DetectionPanel::ShowResult(std::shared_ptr<const Detector> detector,
                                std::shared_ptr<const DetectionResult> result) {
  result_detector_ = std::move(detector);
  result_ = std::move(result);
  FillDetectionTable(table_, result_->detections);
  timings_->setText(FormatStageTimings(result_->timings));
  LogInfo(std::to_string(result_->detections.size()) + " detection(s) in " +
          source_.Describe().toStdString() + ", " + timings_->text().toStdString());
  options_->SaveSettings();
  RefreshImage();
  UpdateLegend();
  emit DetectionFinished();
}

void DetectionPanel::OnArchiveChanged() {
  result_ = nullptr;
  result_detector_ = nullptr;
  FillDetectionTable(table_, {});
  timings_->clear();
  RefreshImage();
  UpdateLegend();
  UpdateCoverage();
  UpdateState();
  if (detect_on_load_->isChecked() && capture_ != nullptr && session_->archive() != nullptr) {
    Detect();
  }
}

OverlayToggles DetectionPanel::overlays() const {
  return {toggles_[0]->isChecked(), toggles_[1]->isChecked(), toggles_[2]->isChecked(),
          toggles_[3]->isChecked()};
}

void DetectionPanel::SetOverlays(const OverlayToggles& toggles) {
  const bool values[4] = {toggles.regions, toggles.coarse, toggles.matches, toggles.poses};
  for (int i = 0; i < 4; ++i) toggles_[i]->setChecked(values[i]);
}

void DetectionPanel::RefreshImage() {
  if (capture_ == nullptr) return image_->SetImage({});
  if (result_ == nullptr || result_detector_ == nullptr) {
    return image_->SetImage(ToQImage(capture_->color));
  }
  image_->SetImage(
      ToQImage(ComposeStageOverlays(*capture_, *result_, *result_detector_, overlays())));
}

void DetectionPanel::UpdateCoverage() {
  const auto archive = session_->archive();
  // Built once per template set, not once per frame stepped to.
  if (archive != envelopes_archive_) {
    envelopes_archive_ = archive;
    envelopes_ = archive == nullptr ? ObjectEnvelopes{} : ObjectEnvelopes(*archive);
  }
  coverage_ =
      archive == nullptr ? std::vector<GroundTruthCoverage>{} : envelopes_.Check(ground_truth_);
  coverage_label_->setText(CoverageHtml(coverage_));
  coverage_label_->setVisible(!coverage_.empty());
  emit CoverageChanged();
}

void DetectionPanel::UpdateLegend() {
  const auto archive = session_->archive();
  QString html;
  if (archive != nullptr) {
    for (const ArchiveObject& object : archive->manifest().objects) html += LegendHtml(object);
  }
  legend_->setText(html);
}

QString DetectionPanel::ArchiveText() const {
  const auto archive = session_->archive();
  if (archive == nullptr) return tr("no template set");
  if (session_->archive_path().isEmpty()) return tr("the trained set");
  return QStringLiteral("“%1”").arg(QFileInfo(session_->archive_path()).fileName());
}

void DetectionPanel::UpdateState() {
  const auto archive = session_->archive();
  archive_label_->setText(
      archive == nullptr
          ? tr("No template set: train one or open an archive.")
          : tr("Templates: %1, %2 templates").arg(ArchiveText()).arg(archive->templates().size()));
  detect_->setEnabled(can_detect());
  emit StateChanged();
}

}  // namespace layermod::ui
