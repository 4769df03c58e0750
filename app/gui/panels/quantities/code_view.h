// The code view: a read-only listing of one source file of the physics, with line
// numbers, in a monospace font, opened at the line that computed a traced number.
// That line is highlighted and scrolled into view with a few lines above it, so the
// equation comment written above each numerical step (docs/architecture.md,
// "Equations above the code") is on screen too. A header names the file and line.
#pragma once

#include <QWidget>

class QLabel;

namespace rbw {

class CodeText;

class CodeView : public QWidget {
    Q_OBJECT
public:
    // Lines shown above the highlighted one when it is scrolled to.
    static constexpr int kContextLines = 4;

    explicit CodeView(QWidget* parent = nullptr);

    // Opens a file of the source tree (a path relative to its root, as a trace entry
    // names it; see source_root.h) at a line (1-based). False, with the reason in the
    // view, when the file cannot be found or read.
    bool showSource(const QString& relativePath, int line);
    // The same for any file; `label` is what the header calls it.
    bool showFile(const QString& path, const QString& label, int line);

    // What the view shows: the header's file (the label), the highlighted line
    // (1-based, 0 when none), the text of a line, and the first line on screen.
    QString file() const { return file_; }
    int highlightedLine() const { return line_; }
    QString lineText(int line) const;
    int firstVisibleLine() const;
    // True when the whole line is inside the visible part of the view.
    bool lineOnScreen(int line) const;
    QString headerText() const;

private:
    void showProblem(const QString& label, const QString& problem);

    QLabel* header_ = nullptr;
    CodeText* text_ = nullptr;
    QString file_;
    int line_ = 0;
};

} // namespace rbw
