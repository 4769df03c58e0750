// The workbook's main window: the lesson list, the quantities table of the current
// step (a TraceModel over the trace), the lesson text, and Step / Play / Reset.
#pragma once

#include "app/core/lesson_catalogue.h"
#include "physics/trace.h"
#include "physics/world.h"

#include <QMainWindow>

#include <memory>

class QAction;
class QLabel;
class QListWidget;
class QTextBrowser;
class QTimer;
class QTreeView;

namespace rbw {

class TraceModel;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens a lesson by folder id ("01-one-step"); false if it cannot be loaded.
    bool openLesson(const QString& id);
    QString currentLessonId() const { return currentLesson_.id; }
    TraceModel* traceModel() const { return traceModel_; }
    const World* world() const { return world_.get(); }

public slots:
    void stepOnce();
    void setPlaying(bool playing);
    void resetLesson();
    void copySelection(bool asLatex);

private:
    void createActions();
    void createLayout();
    void showTrace();
    void updateStatus();
    void onLessonRowChanged(int row);

    QList<Lesson> lessons_;
    Lesson currentLesson_;
    std::unique_ptr<World> world_;
    StepTrace trace_;

    QListWidget* lessonList_ = nullptr;
    QTreeView* traceView_ = nullptr;
    TraceModel* traceModel_ = nullptr;
    QTextBrowser* lessonText_ = nullptr;
    QLabel* statusLabel_ = nullptr;
    QTimer* playTimer_ = nullptr;
    QAction* stepAction_ = nullptr;
    QAction* playAction_ = nullptr;
    QAction* resetAction_ = nullptr;
};

} // namespace rbw
