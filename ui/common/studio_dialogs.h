// SPDX-License-Identifier: MIT
#pragma once

#include <QString>

class QWidget;

namespace layermod::ui {

class StudioSession;

// Batch mode (a --screenshot run): errors go to stderr instead of a dialog, prompts answer yes.
void SetBatchMode(bool batch);
bool BatchMode();
int BatchErrorCount();

// A modal error box: `action` names what failed and the file ("Open mesh “part.stl”"),
// `message` is the core's explanation.
void ShowError(QWidget* parent, const QString& action, const QString& message);

// Tests set this variable to "1" so that discarding an unexported set never blocks on a prompt.
inline constexpr char kDiscardWithoutAskingEnv[] = "LAYERMOD_STUDIO_DISCARD_WITHOUT_ASKING";

// True when there is no unexported trained set, or the user agrees to discard it.
bool ConfirmDiscardUnsaved(QWidget* parent, const StudioSession& session);

// The form has changed since the shown set was made: true when the user still wants to export
// the set as it was made.
bool ConfirmExportStale(QWidget* parent);

// File dialogs that start in (and remember) the last directory used for `kind` ("mesh",
// "archive", "profile", "camera"). Empty when cancelled.
QString AskOpenPath(QWidget* parent, const QString& kind, const QString& title,
                    const QString& filter);
QString AskSavePath(QWidget* parent, const QString& kind, const QString& title,
                    const QString& filter, const QString& suggested_name);

// Filters shared by the dialogs.
QString MeshFileFilter();
QString ArchiveFileFilter();
QString JsonFileFilter();

}  // namespace layermod::ui
