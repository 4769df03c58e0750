// Helpers for the tests that drive the whole window (tst_app, tst_quantities_table,
// tst_window_controls, tst_lesson_controller, tst_settings_fuzz): rows of the
// quantities table, the typeset page's text, warnings caught while a lesson runs,
// mouse events on the 3D view, and the main() every window test needs.
#pragma once

#include "app/gui/panels/derivation/derivation_view.h"
#include "app/gui/panels/quantities/trace_model.h"
#include "app/gui/panels/view/scene_view.h"

#include <QApplication>
#include <QDeadlineTimer>
#include <QMouseEvent>
#include <QSignalSpy>
#include <QSurfaceFormat>
#include <QWebEnginePage>
#include <QtTest>

#include <mutex>

namespace rbw::test {

// Depth-first search for the row whose IdRole is `id` (optionally under `parent`).
inline QModelIndex findRow(const QAbstractItemModel* model, const QString& id, const QModelIndex& parent = {})
{
    for (int r = 0; r < model->rowCount(parent); ++r) {
        const QModelIndex i = model->index(r, 0, parent);
        if (model->data(i, TraceModel::IdRole).toString() == id) return i;
        const QModelIndex found = findRow(model, id, i);
        if (found.isValid()) return found;
    }
    return {};
}

inline QString valueText(const QAbstractItemModel* model, const QModelIndex& row)
{
    return model->index(row.row(), TraceModel::ValueColumn, row.parent()).data().toString();
}

// Warnings printed while a lesson loads and steps: a test fails on any of ours.
// Chromium's and Mesa's own chatter goes to stderr without Qt's handler and is not
// caught here; Qt's own GL/WebEngine categories are listed as noise explicitly.
struct Warnings {
    QStringList caught;
    std::mutex mutex;
    QtMessageHandler previous = nullptr;

    static Warnings& instance()
    {
        static Warnings w;
        return w;
    }
    static void handler(QtMsgType type, const QMessageLogContext& context, const QString& message)
    {
        Warnings& w = instance();
        if (type == QtWarningMsg || type == QtCriticalMsg) {
            const QString category = QString::fromLatin1(context.category ? context.category : "");
            const bool noise = category.startsWith("qt.webengine") || category.startsWith("js") ||
                               message.contains("XDG_RUNTIME_DIR") || message.contains("Core Profile was requested");
            if (!noise) {
                std::lock_guard<std::mutex> lock(w.mutex);
                w.caught << QStringLiteral("[%1] %2").arg(category, message);
            }
        }
        if (w.previous) w.previous(type, context, message);
    }
    static void install() { instance().previous = qInstallMessageHandler(&Warnings::handler); }
    static void clear()
    {
        std::lock_guard<std::mutex> lock(instance().mutex);
        instance().caught.clear();
    }
    static QStringList list()
    {
        std::lock_guard<std::mutex> lock(instance().mutex);
        return instance().caught;
    }
};

// The derivation page's text as the browser shows it; empty if it never answered
// (the caller's checks then fail).
inline QString pageText(DerivationView* view)
{
    QString text;
    bool done = false;
    view->page()->runJavaScript("document.body.innerText", [&](const QVariant& v) {
        text = v.toString();
        done = true;
    });
    QDeadlineTimer deadline(10000);
    while (!done && !deadline.hasExpired()) QTest::qWait(20);
    return text;
}

inline bool waitRendered(DerivationView* view)
{
    QSignalSpy spy(view, &DerivationView::rendered);
    return spy.wait(20000) || view->isRendered();
}

inline QPoint toPoint(const QPointF& p) { return QPoint(qRound(p.x()), qRound(p.y())); }

inline void sendMouse(QWidget* w, QEvent::Type type, const QPoint& pos, Qt::MouseButton button, Qt::MouseButtons buttons)
{
    QMouseEvent e(type, QPointF(pos), w->mapToGlobal(QPointF(pos)), button, buttons, Qt::NoModifier);
    QApplication::sendEvent(w, &e);
}

} // namespace rbw::test

// As in the app's main(): shared GL contexts for QtWebEngine and the 3D view; the
// settings under the tests' own organisation name.
#define RBW_WINDOW_TEST_MAIN(TestClass)                                        \
    int main(int argc, char* argv[])                                           \
    {                                                                          \
        QCoreApplication::setAttribute(Qt::AA_ShareOpenGLContexts);            \
        QSurfaceFormat::setDefaultFormat(rbw::SceneView::requestedFormat());   \
        QApplication app(argc, argv);                                          \
        QApplication::setOrganizationName("rigid-workbook-tests");             \
        TestClass test;                                                        \
        return QTest::qExec(&test, argc, argv);                                \
    }
