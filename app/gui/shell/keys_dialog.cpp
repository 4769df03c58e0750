#include "app/gui/shell/keys_dialog.h"

#include <QAction>
#include <QDialog>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QKeySequence>
#include <QTableWidget>
#include <QVBoxLayout>

namespace rbw {

QString plainActionText(const QAction* action)
{
    QString t = action->text();
    t.remove('&');
    return t;
}

QList<QAction*> everyShortcutAction(const QWidget* window, const QList<QAction*>& inMenuOrder)
{
    QList<QAction*> out = inMenuOrder;
    if (window == nullptr) return out;
    // Any other action of the window with a key (a panel's own, one added later)
    // is listed too: the dialog cannot miss a key the window has.
    for (QAction* a : window->findChildren<QAction*>()) {
        if (!a->shortcuts().isEmpty() && !out.contains(a)) out << a;
    }
    return out;
}

void showKeysDialog(QWidget* parent, const QList<QAction*>& shortcutActions)
{
    auto* dialog = new QDialog(parent);
    dialog->setObjectName("keysDialog");
    dialog->setWindowTitle(QObject::tr("Keys"));
    dialog->setAttribute(Qt::WA_DeleteOnClose);
    auto* table = new QTableWidget(dialog);
    table->setObjectName("keysTable");
    table->setColumnCount(2);
    table->setHorizontalHeaderLabels({QObject::tr("Action"), QObject::tr("Keys")});
    table->verticalHeader()->hide();
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    QList<QPair<QString, QString>> rows;
    for (const QAction* a : everyShortcutAction(parent, shortcutActions)) {
        QStringList keys;
        for (const QKeySequence& k : a->shortcuts()) keys << k.toString(QKeySequence::NativeText);
        if (!keys.isEmpty()) rows.append({plainActionText(a), keys.join(QObject::tr(" or "))});
    }
    rows.append({QObject::tr("Orbit the camera"), QObject::tr("Left-drag on empty space, or Alt+left-drag")});
    rows.append({QObject::tr("Pan"), QObject::tr("Right- or middle-drag")});
    rows.append({QObject::tr("Zoom"), QObject::tr("Mouse wheel")});
    rows.append({QObject::tr("Pull a box with a spring"), QObject::tr("Left-drag on the box")});
    table->setRowCount(rows.size());
    for (int r = 0; r < rows.size(); ++r) {
        table->setItem(r, 0, new QTableWidgetItem(rows[r].first));
        table->setItem(r, 1, new QTableWidgetItem(rows[r].second));
    }
    table->resizeColumnsToContents();
    table->horizontalHeader()->setStretchLastSection(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
    QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
    auto* layout = new QVBoxLayout(dialog);
    layout->addWidget(table);
    layout->addWidget(buttons);
    dialog->resize(520, 600);
    dialog->show();
}

} // namespace rbw
