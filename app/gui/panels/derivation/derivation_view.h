// The typeset derivation of the current step: a QWebEngineView that shows a page from
// the derivation builder, renders its math with KaTeX (offline, from Debian's
// libjs-katex) and reports when the page is final.
//
// showStep() loads a page; when KaTeX has rendered every formula and the fonts are
// loaded, rendered(katexCount, errorCount) is emitted (errorCount counts .katex-error
// spans: formulas KaTeX could not parse). rendered(-1, -1) means the page did not load
// or did not finish rendering in time. The rendered DOM is kept for exportHtml().
#pragma once

#include <QString>
#include <QWebEngineView>

class QTimer;

namespace rbw {

class DerivationView : public QWebEngineView {
    Q_OBJECT
public:
    explicit DerivationView(QWidget* parent = nullptr);

    // Shows a complete document (derivation_builder.h). Local files under the KaTeX
    // folder are reachable: the page's base URL is katexUrl.
    void showStep(const QString& html);

    // The KaTeX folder the pages refer to (default file:///usr/share/javascript/katex/).
    void setKatexUrl(const QString& url) { katexUrl_ = url; }
    QString katexUrl() const { return katexUrl_; }

    bool isRendered() const { return rendered_; }
    int katexCount() const { return katexCount_; }
    int errorCount() const { return errorCount_; }
    QString renderedBodyHtml() const { return renderedBody_; }

    // Writes the rendered page as one standalone HTML file (no script, KaTeX CSS and
    // woff2 fonts embedded). False with *error set if nothing is rendered yet or the
    // file cannot be written; the file is replaced atomically (QSaveFile).
    bool exportHtml(const QString& path, QString* error);

    // Prints the page (A4 portrait) to memory and writes it with writePdf();
    // pdfExported(path, ok, error) follows, error empty when ok.
    void exportPdf(const QString& path);

    // Writes a printed PDF atomically (QSaveFile): the file at path is replaced
    // completely or not at all. False with *error set if pdf is empty (printing
    // failed) or the file cannot be written.
    static bool writePdf(const QString& path, const QByteArray& pdf, QString* error);

signals:
    void rendered(int katexCount, int errorCount);
    void pdfExported(const QString& path, bool ok, const QString& error);

private:
    void onLoadFinished(bool ok);
    void poll();
    void finish(int katexCount, int errorCount);

    QString katexUrl_;
    QTimer* pollTimer_ = nullptr;
    int generation_ = 0;     // the load a poll result belongs to
    int pollsLeft_ = 0;
    bool rendered_ = false;
    int katexCount_ = 0;
    int errorCount_ = 0;
    QString renderedBody_;
    QString title_;
};

} // namespace rbw
