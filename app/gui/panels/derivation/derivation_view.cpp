#include "app/gui/panels/derivation/derivation_view.h"

#include "app/output/atomic_file.h"

#include "app/derivation/derivation_page.h"
#include "app/derivation/standalone_html.h"

#include <QPointer>
#include <QTimer>
#include <QUrl>
#include <QVariantMap>
#include <QWebEnginePage>
#include <QWebEngineSettings>

namespace rbw {

namespace {
constexpr int kPollMs = 40;
constexpr int kMaxPolls = 500;   // 20 s for KaTeX and the fonts, then give up
}

DerivationView::DerivationView(QWidget* parent)
    : QWebEngineView(parent), katexUrl_(defaultKatexUrl()), pollTimer_(new QTimer(this))
{
    // The page loads KaTeX from file:// and nothing from the network.
    settings()->setAttribute(QWebEngineSettings::LocalContentCanAccessFileUrls, true);
    settings()->setAttribute(QWebEngineSettings::LocalContentCanAccessRemoteUrls, false);
    settings()->setAttribute(QWebEngineSettings::JavascriptEnabled, true);
    page()->setBackgroundColor(QColor(0xfb, 0xfa, 0xf7));
    setMinimumWidth(200);
    // No browser menu (its Back showed step 0 at step 2, issue 20): Copy and Select all only.
    setContextMenuPolicy(Qt::ActionsContextMenu);
    addAction(pageAction(QWebEnginePage::Copy));
    addAction(pageAction(QWebEnginePage::SelectAll));

    pollTimer_->setInterval(kPollMs);
    connect(pollTimer_, &QTimer::timeout, this, &DerivationView::poll);
    connect(this, &QWebEngineView::loadFinished, this, &DerivationView::onLoadFinished);
}

void DerivationView::showStep(const QString& html)
{
    ++generation_;
    pollTimer_->stop();
    rendered_ = false;
    katexCount_ = 0;
    errorCount_ = 0;
    renderedBody_.clear();
    title_.clear();
    setHtml(html, QUrl(katexUrl_));
}

void DerivationView::onLoadFinished(bool ok)
{
    if (!ok) {
        finish(-1, -1);
        return;
    }
    pollsLeft_ = kMaxPolls;
    pollTimer_->start();
    poll();
}

void DerivationView::poll()
{
    if (--pollsLeft_ < 0) {
        pollTimer_->stop();
        finish(-1, -1);
        return;
    }
    const int generation = generation_;
    // One call returns the counts and, once rendered, the rendered DOM for exportHtml.
    page()->runJavaScript(
        QStringLiteral("(function () { var r = window.rbwRender; if (!r) return null;"
                       " return {katex: r.katex, errors: r.errors, body: document.body.innerHTML,"
                       " title: document.title}; })()"),
        [this, generation](const QVariant& v) {
            if (generation != generation_ || rendered_ || !v.isValid() || v.isNull()) return;
            const QVariantMap m = v.toMap();
            if (m.isEmpty()) return;
            pollTimer_->stop();
            renderedBody_ = m.value(QStringLiteral("body")).toString();
            title_ = m.value(QStringLiteral("title")).toString();
            finish(m.value(QStringLiteral("katex")).toInt(), m.value(QStringLiteral("errors")).toInt());
        });
}

void DerivationView::finish(int katexCount, int errorCount)
{
    pollTimer_->stop();
    rendered_ = katexCount >= 0;
    katexCount_ = katexCount;
    errorCount_ = errorCount;
    emit rendered(katexCount, errorCount);
}

bool DerivationView::exportHtml(const QString& path, QString* error)
{
    if (!rendered_ || renderedBody_.isEmpty()) {
        if (error != nullptr) *error = QStringLiteral("the derivation is not rendered yet");
        return false;
    }
    const QString html = standaloneDerivationHtml(renderedBody_, title_, QUrl(katexUrl_).toLocalFile(), error);
    if (html.isEmpty()) return false;
    return writeFileAtomically(path, html.toUtf8(), error);
}

void DerivationView::exportPdf(const QString& path)
{
    // printToPdf(path) would let Chromium write the file in place, so a failure could
    // leave half a PDF behind. Print to memory instead and write that atomically.
    const QPointer<DerivationView> self(this);
    page()->printToPdf([self, path](const QByteArray& pdf) {
        if (self.isNull()) return;
        QString error;
        const bool ok = writePdf(path, pdf, &error);
        emit self->pdfExported(path, ok, error);
    });
}

bool DerivationView::writePdf(const QString& path, const QByteArray& pdf, QString* error)
{
    if (pdf.isEmpty()) {
        if (error != nullptr) *error = QStringLiteral("cannot write %1: printing the page failed").arg(path);
        return false;
    }
    return writeFileAtomically(path, pdf, error);
}

} // namespace rbw
