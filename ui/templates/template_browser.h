// SPDX-License-Identifier: MIT
#pragma once

#include <QWidget>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QListView;
class QPushButton;

namespace layermod::ui {

class StudioSession;
class TemplateListModel;

// The template set as thumbnails (render + features), filtered by layer and view; a click shows
// the template enlarged and its camera in the 3D view.
class TemplateBrowser : public QWidget {
  Q_OBJECT

 public:
  explicit TemplateBrowser(StudioSession* session, QWidget* parent = nullptr);

  TemplateListModel* list_model() const { return model_; }
  QListView* list_view() const { return list_; }
  // Shows row `row` of the (filtered) list enlarged and announces its camera.
  void SelectRow(int row);
  bool has_mesh() const;

 signals:
  // A template (index in the session archive's table) was picked.
  void TemplateSelected(int template_index);
  void OpenMeshRequested();

 private:
  void Refresh();  // archive or model changed
  void ApplyFilter();
  void FillLayers();
  QWidget* BuildFilterRow();
  void ShowDetail(int row);   // -1: none
  void ShowCurrent(int row);  // detail and TemplateSelected

  StudioSession* session_ = nullptr;
  TemplateListModel* model_ = nullptr;
  QListView* list_ = nullptr;
  QComboBox* layer_ = nullptr;
  QDoubleSpinBox* elevation_min_ = nullptr;
  QDoubleSpinBox* elevation_max_ = nullptr;
  QDoubleSpinBox* azimuth_min_ = nullptr;
  QDoubleSpinBox* azimuth_max_ = nullptr;
  QDoubleSpinBox* roll_min_ = nullptr;
  QDoubleSpinBox* roll_max_ = nullptr;
  QLabel* count_ = nullptr;
  QWidget* mesh_banner_ = nullptr;
  QLabel* mesh_banner_text_ = nullptr;
  QLabel* detail_image_ = nullptr;
  QLabel* detail_text_ = nullptr;
};

}  // namespace layermod::ui
