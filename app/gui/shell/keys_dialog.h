// Help → Keys: every action with a keyboard shortcut, in menu order, then any other
// action of the window that has one (so the list cannot go stale), and the mouse
// gestures of the 3D view (objectName "keysDialog", its table "keysTable").
#pragma once

#include <QList>
#include <QString>

class QAction;
class QWidget;

namespace rbw {

// An action's text without its mnemonic ampersands ("&Step" -> "Step").
QString plainActionText(const QAction* action);

// The actions the dialog lists: inMenuOrder, then every other action under the
// window that has a shortcut.
QList<QAction*> everyShortcutAction(const QWidget* window, const QList<QAction*>& inMenuOrder);

// Opens the dialog (non-modal, deleted on close).
void showKeysDialog(QWidget* parent, const QList<QAction*>& shortcutActions);

} // namespace rbw
