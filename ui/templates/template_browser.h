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

  StudioSession* session_;
  TemplateListModel* model_;
  QListView* list_;
  QComboBox* layer_;
  QDoubleSpinBox* elevation_min_;
  QDoubleSpinBox* elevation_max_;
  QDoubleSpinBox* azimuth_min_;
  QDoubleSpinBox* azimuth_max_;
  QDoubleSpinBox* roll_min_;
  QDoubleSpinBox* roll_max_;
  QLabel* count_;
  QWidget* mesh_banner_;
  QLabel* mesh_banner_text_;
  QLabel* detail_image_;
  QLabel* detail_text_;
};

}  // namespace layermod::ui
