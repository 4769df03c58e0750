// Help → Keys: every action with a keyboard shortcut, in menu order, and the mouse
// gestures of the 3D view (objectName "keysDialog", its table "keysTable").
#pragma once

#include <QList>
#include <QString>

class QAction;
class QWidget;

namespace rbw {

// An action's text without its mnemonic ampersands ("&Step" -> "Step").
QString plainActionText(const QAction* action);

// Opens the dialog (non-modal, deleted on close).
void showKeysDialog(QWidget* parent, const QList<QAction*>& shortcutActions);

} // namespace rbw
