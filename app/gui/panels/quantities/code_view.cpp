#include "app/gui/panels/quantities/code_view.h"

#include "app/core/source_root.h"

#include <QFile>
#include <QFontDatabase>
#include <QLabel>
#include <QPainter>
#include <QPlainTextEdit>
#include <QRegularExpression>
#include <QScrollBar>
#include <QSyntaxHighlighter>
#include <QTextBlock>
#include <QVBoxLayout>

namespace rbw {

namespace {

const QColor kHighlight(255, 236, 160);
const QColor kGutter(244, 244, 240);
const QColor kGutterText(150, 150, 150);
const QColor kComment(60, 110, 60);

// Comments in green: in the physics they hold the equations, which a student reads
// against the slides.
class CommentHighlighter : public QSyntaxHighlighter {
public:
    using QSyntaxHighlighter::QSyntaxHighlighter;

protected:
    void highlightBlock(const QString& text) override
    {
        QTextCharFormat comment;
        comment.setForeground(kComment);
        int i = 0;
        int start = previousBlockState() == 1 ? 0 : -1;   // a /* ... */ left open above
        for (;;) {
            if (start >= 0) {
                const int end = text.indexOf(QLatin1String("*/"), i);
                if (end < 0) {
                    setFormat(start, text.size() - start, comment);
                    setCurrentBlockState(1);
                    return;
                }
                setFormat(start, end + 2 - start, comment);
                i = end + 2;
                start = -1;
            }
            const int line = text.indexOf(QLatin1String("//"), i);
            const int block = text.indexOf(QLatin1String("/*"), i);
            if (line < 0 && block < 0) break;
            if (block < 0 || (line >= 0 && line < block)) {
                setFormat(line, text.size() - line, comment);
                break;
            }
            start = block;
            i = block + 2;
        }
        setCurrentBlockState(0);
    }
};

} // namespace

// The text with a gutter of line numbers on its left (Qt's "Code Editor" example).
class CodeText : public QPlainTextEdit {
public:
    explicit CodeText(QWidget* parent = nullptr)
        : QPlainTextEdit(parent)
        , gutter_(new Gutter(this))
    {
        setReadOnly(true);
        setLineWrapMode(QPlainTextEdit::NoWrap);
        setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
        setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
        new CommentHighlighter(document());
        connect(this, &QPlainTextEdit::blockCountChanged, this, [this] { updateGutterWidth(); });
        connect(this, &QPlainTextEdit::updateRequest, this, &CodeText::onUpdateRequest);
        updateGutterWidth();
    }

    int gutterWidth() const
    {
        const int digits = QString::number(std::max(1, blockCount())).size();
        return 12 + fontMetrics().horizontalAdvance(QLatin1Char('9')) * std::max(3, digits);
    }

    void setMarkedLine(int line) { marked_ = line; gutter_->update(); }

    bool blockOnScreen(int number) const
    {
        const QTextBlock block = document()->findBlockByNumber(number);
        if (!block.isValid()) return false;
        const QRectF r = blockBoundingGeometry(block).translated(contentOffset());
        return r.top() >= 0 && r.bottom() <= viewport()->height();
    }

    void paintGutter(QPaintEvent* event)
    {
        QPainter painter(gutter_);
        painter.fillRect(event->rect(), kGutter);
        QTextBlock block = firstVisibleBlock();
        int top = qRound(blockBoundingGeometry(block).translated(contentOffset()).top());
        int bottom = top + qRound(blockBoundingRect(block).height());
        while (block.isValid() && top <= event->rect().bottom()) {
            if (block.isVisible() && bottom >= event->rect().top()) {
                const int number = block.blockNumber() + 1;
                QFont f = font();
                f.setBold(number == marked_);
                painter.setFont(f);
                painter.setPen(number == marked_ ? palette().color(QPalette::Text) : kGutterText);
                painter.drawText(0, top, gutter_->width() - 6, fontMetrics().height(), Qt::AlignRight,
                                 QString::number(number));
            }
            block = block.next();
            top = bottom;
            bottom = top + qRound(blockBoundingRect(block).height());
        }
    }

protected:
    void resizeEvent(QResizeEvent* event) override
    {
        QPlainTextEdit::resizeEvent(event);
        const QRect r = contentsRect();
        gutter_->setGeometry(QRect(r.left(), r.top(), gutterWidth(), r.height()));
    }

private:
    class Gutter : public QWidget {
    public:
        explicit Gutter(CodeText* text) : QWidget(text), text_(text) {}
        QSize sizeHint() const override { return {text_->gutterWidth(), 0}; }

    protected:
        void paintEvent(QPaintEvent* event) override { text_->paintGutter(event); }

    private:
        CodeText* text_;
    };

    void updateGutterWidth() { setViewportMargins(gutterWidth(), 0, 0, 0); }

    void onUpdateRequest(const QRect& rect, int dy)
    {
        if (dy != 0) gutter_->scroll(0, dy);
        else gutter_->update(0, rect.y(), gutter_->width(), rect.height());
        if (rect.contains(viewport()->rect())) updateGutterWidth();
    }

    Gutter* gutter_;
    int marked_ = 0;
};

CodeView::CodeView(QWidget* parent)
    : QWidget(parent)
    , header_(new QLabel)
    , text_(new CodeText)
{
    header_->setObjectName("codeHeader");
    header_->setTextInteractionFlags(Qt::TextSelectableByMouse);
    header_->setContentsMargins(6, 3, 6, 3);
    header_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    header_->setText(tr("Select a row of the quantities table and choose Show code (F2)."));
    text_->setObjectName("codeText");
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addWidget(header_);
    layout->addWidget(text_, 1);
}

bool CodeView::showSource(const QString& relativePath, int line)
{
    const QString path = sourceFilePath(relativePath);
    if (path.isEmpty()) {
        const QString root = sourceRoot();
        showProblem(relativePath,
                    root.isEmpty() ? tr("The source tree was not found: set RBW_SOURCE_ROOT to the folder that holds "
                                        "physics/.")
                                   : tr("%1 is not in the source tree at %2.").arg(relativePath, root));
        return false;
    }
    return showFile(path, relativePath, line);
}

bool CodeView::showFile(const QString& path, const QString& label, int line)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text)) {
        showProblem(label, tr("Cannot read %1: %2").arg(path, f.errorString()));
        return false;
    }
    text_->setPlainText(QString::fromUtf8(f.readAll()));
    file_ = label;
    line_ = (line >= 1 && line <= text_->blockCount()) ? line : 0;
    header_->setText(headerText());
    text_->setMarkedLine(line_);

    QList<QTextEdit::ExtraSelection> marks;
    if (line_ > 0) {
        const QTextBlock block = text_->document()->findBlockByNumber(line_ - 1);
        QTextEdit::ExtraSelection mark;
        mark.format.setBackground(kHighlight);
        mark.format.setProperty(QTextFormat::FullWidthSelection, true);
        mark.cursor = QTextCursor(block);
        marks << mark;
        text_->setTextCursor(QTextCursor(block));
        // The line, with the equation comment above it: the line kContextLines from
        // the top of the view. Without wrapping, the scroll bar counts lines.
        text_->verticalScrollBar()->setValue(std::max(0, line_ - 1 - kContextLines));
    } else {
        text_->verticalScrollBar()->setValue(0);
    }
    text_->setExtraSelections(marks);
    return true;
}

void CodeView::showProblem(const QString& label, const QString& problem)
{
    file_ = label;
    line_ = 0;
    text_->setPlainText(problem);
    text_->setExtraSelections({});
    text_->setMarkedLine(0);
    header_->setText(label);
}

QString CodeView::lineText(int line) const
{
    const QTextBlock block = text_->document()->findBlockByNumber(line - 1);
    return block.isValid() && line >= 1 ? block.text() : QString();
}

int CodeView::firstVisibleLine() const
{
    return text_->verticalScrollBar()->value() + 1;
}

bool CodeView::lineOnScreen(int line) const
{
    return text_->blockOnScreen(line - 1);
}

QString CodeView::headerText() const
{
    return line_ > 0 ? QStringLiteral("%1:%2").arg(file_).arg(line_) : file_;
}

} // namespace rbw
