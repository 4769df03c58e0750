#include "app/derivation/derivation_page.h"

#include <QRegularExpression>

namespace rbw {

QString defaultKatexUrl()
{
    return QStringLiteral("file:///usr/share/javascript/katex/");
}

QString derivationCss()
{
    return QStringLiteral(R"CSS(
html { background: #fbfaf7; color-scheme: light; }
body { margin: 0; padding: 10px 16px 28px; background: #fbfaf7; color: #1f2328;
       font: 15px/1.5 "DejaVu Sans", "Noto Sans", "Liberation Sans", Arial, sans-serif; }
main.derivation { max-width: 48em; counter-reset: sec; }
h1 { font-size: 1.22em; font-weight: 600; margin: 0.2em 0 0.3em; }
h2 { font-size: 1.06em; font-weight: 600; margin: 1.2em 0 0.35em; padding-bottom: 2px;
     border-bottom: 1px solid #e0dacd; counter-increment: sec; counter-reset: sub; }
h2::before { content: counter(sec) ".\00a0\00a0"; color: #9a7a3c; }
h3 { font-size: 0.98em; font-weight: 600; margin: 0.9em 0 0.25em; counter-increment: sub; }
h3::before { content: counter(sec) "." counter(sub) "\00a0\00a0"; color: #9a7a3c; }
p, li { margin: 0.35em 0; }
ul { padding-left: 1.3em; margin: 0.3em 0; }
.stepinfo { color: #59636e; font-size: 0.92em; margin-bottom: 0.6em; }
.row { margin: 0.25em 0 0.55em; padding: 1px 0 2px 0.6em; border-left: 3px solid #e7e1d3;
       overflow-x: auto; overflow-y: hidden; }
.row .katex-display { margin: 0.1em 0; text-align: left; }
.row .katex-display > .katex { text-align: left; }
.katex { font-size: 1.08em; }
.missing { color: #b3261e; font-style: italic; }
.template-error { border: 1px solid #d4a29c; background: #fdeeec; color: #7a1d15; padding: 8px 10px;
                  border-radius: 4px; margin: 0.5em 0 1em; }
.template-error pre { white-space: pre-wrap; margin: 0.3em 0 0; font-size: 0.9em; }
.note { color: #59636e; font-size: 0.92em; }
@media print { html, body { background: #ffffff; } .row { overflow: visible; } }
)CSS");
}

namespace {

QString renderScript()
{
    // Renders every .tex element, then waits for layout and the fonts before it
    // reports the counts, so a grab or a PDF taken afterwards shows the final glyphs.
    return QStringLiteral(R"JS(
document.addEventListener('DOMContentLoaded', function () {
  var nodes = document.querySelectorAll('.tex');
  if (typeof katex === 'undefined') {
    var box = document.createElement('div');
    box.className = 'template-error';
    box.textContent = 'KaTeX could not be loaded (package libjs-katex): the formulas are shown as LaTeX.';
    document.body.insertBefore(box, document.body.firstChild);
    window.rbwRender = {katex: 0, errors: nodes.length, failed: true};
    return;
  }
  var options = function (el) {
    return {displayMode: el.classList.contains('display'), throwOnError: false, strict: 'ignore',
            output: 'htmlAndMathml'};
  };
  // Rows: the one-line form (data-inline) where it fits the width, else the stacked
  // aligned form, which is the element's text.
  var rows = [];
  for (var i = 0; i < nodes.length; ++i) {
    var el = nodes[i];
    el.rbwTex = el.textContent;
    if (el.hasAttribute('data-inline')) rows.push(el);
    katex.render(el.hasAttribute('data-inline') ? el.getAttribute('data-inline') : el.rbwTex, el, options(el));
  }
  var fit = function () {
    for (var j = 0; j < rows.length; ++j) {
      var row = rows[j], box = row.parentNode;
      katex.render(row.getAttribute('data-inline'), row, options(row));
      if (box.scrollWidth > box.clientWidth + 1) katex.render(row.rbwTex, row, options(row));
    }
  };
  fit();
  var pending = null;
  window.addEventListener('resize', function () {
    clearTimeout(pending);
    pending = setTimeout(fit, 100);
  });
  void document.body.offsetHeight;
  document.fonts.ready.then(function () {
    window.rbwRender = {katex: document.querySelectorAll('.katex').length,
                        errors: document.querySelectorAll('.katex-error').length};
  });
});
)JS");
}

// Position of the first relation at brace depth 0, and its length; -1 if none.
int findRelation(const QString& tex, int* length)
{
    int depth = 0;
    for (int i = 0; i < tex.size(); ++i) {
        const QChar c = tex[i];
        if (c == QLatin1Char('\\')) {
            for (const QLatin1String rel : {QLatin1String("\\leftarrow"), QLatin1String("\\approx")}) {
                if (depth == 0 && tex.mid(i).startsWith(rel) &&
                    (i + rel.size() >= tex.size() || !tex[i + rel.size()].isLetter())) {
                    *length = rel.size();
                    return i;
                }
            }
            ++i;   // skip the escaped character, e.g. \{ or \=
            continue;
        }
        if (c == QLatin1Char('{')) ++depth;
        if (c == QLatin1Char('}')) --depth;
        if (c == QLatin1Char('=') && depth == 0) {
            *length = 1;
            return i;
        }
    }
    return -1;
}

} // namespace

QString derivationPage(const QString& bodyHtml, const QString& title, const QString& katexUrl)
{
    QString base = katexUrl;
    if (!base.endsWith(QLatin1Char('/'))) base += QLatin1Char('/');
    return QStringLiteral("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
                          "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
                          "<title>%1</title>\n"
                          "<link rel=\"stylesheet\" href=\"%2katex.min.css\">\n"
                          "<style>%3</style>\n"
                          "<script src=\"%2katex.min.js\"></script>\n"
                          "<script>%4</script>\n"
                          "</head>\n<body>\n<main class=\"derivation\">\n%5</main>\n</body>\n</html>\n")
        .arg(htmlEscape(title), htmlEscape(base), derivationCss(), renderScript(), bodyHtml);
}

QString htmlEscape(const QString& text)
{
    return text.toHtmlEscaped();
}

QString latexTextEscape(const QString& text)
{
    QString out;
    for (const QChar c : text) {
        switch (c.unicode()) {
        case '\\': out += QLatin1String("\\textbackslash{}"); break;
        case '{': case '}': case '_': case '%': case '$': case '#': case '&':
            out += QLatin1Char('\\');
            out += c;
            break;
        case '^': out += QLatin1String("\\textasciicircum{}"); break;
        case '~': out += QLatin1String("\\textasciitilde{}"); break;
        default: out += c;
        }
    }
    return out;
}

QString unitLatex(const QString& unit)
{
    if (unit.isEmpty()) return QString();
    QString u = unit;
    u.replace(QString::fromUtf8("·"), QLatin1String("\\cdot "));
    u.replace(QString::fromUtf8("²"), QLatin1String("^{2}"));
    u.replace(QString::fromUtf8("³"), QLatin1String("^{3}"));
    return QStringLiteral("\\mathrm{%1}").arg(u);
}

QString rowLatex(const QString& formula, const QString& substituted, const QString& result)
{
    QStringList lines;
    const QString shownResult =
        result.isEmpty() ? QString() : QStringLiteral("\\textcolor{#0b4f8a}{%1}").arg(result);
    int relLength = 0;
    const int rel = findRelation(formula, &relLength);
    QStringList rest;
    if (!substituted.isEmpty()) rest << substituted;
    if (!shownResult.isEmpty()) rest << shownResult;
    if (rel >= 0) {
        lines << formula.left(rel).trimmed() + QLatin1String(" &") + formula.mid(rel);
        for (const QString& r : rest) lines << QStringLiteral("&= ") + r;
    } else if (rest.isEmpty()) {
        lines << formula;
    } else {
        lines << formula + QStringLiteral(" &= ") + rest.takeFirst();
        for (const QString& r : rest) lines << QStringLiteral("&= ") + r;
    }
    return QStringLiteral("\\begin{aligned} ") + lines.join(QStringLiteral(" \\\\[3pt] ")) +
           QStringLiteral(" \\end{aligned}");
}

QString texExponents(const QString& latex)
{
    // A number in e-notation (not a letter or command before it, no letter after it).
    static const QRegularExpression e(QStringLiteral(R"((?<![A-Za-z0-9.#\\])(\d+(?:\.\d+)?)e([+-]?)0*(\d+)(?![A-Za-z]))"));
    QString out;
    qsizetype from = 0;
    QRegularExpressionMatchIterator it = e.globalMatch(latex);
    while (it.hasNext()) {
        const QRegularExpressionMatch m = it.next();
        out += latex.mid(from, m.capturedStart() - from);
        const QString sign = m.captured(2) == QLatin1String("-") ? QStringLiteral("-") : QString();
        out += QStringLiteral("%1 \\cdot 10^{%2%3}").arg(m.captured(1), sign, m.captured(3));
        from = m.capturedEnd();
    }
    return out + latex.mid(from);
}

QString rowHtml(const QString& latex, const QString& inlineLatex)
{
    if (inlineLatex.isEmpty()) {
        return QStringLiteral("<div class=\"row\"><div class=\"tex display\">%1</div></div>\n").arg(htmlEscape(texExponents(latex)));
    }
    return QStringLiteral("<div class=\"row\"><div class=\"tex display\" data-inline=\"%1\">%2</div></div>\n")
        .arg(htmlEscape(texExponents(inlineLatex)), htmlEscape(texExponents(latex)));
}

QString rowInlineLatex(const QString& formula, const QString& substituted, const QString& result)
{
    QStringList parts{formula};
    if (!substituted.isEmpty()) parts << substituted;
    if (!result.isEmpty()) parts << QStringLiteral("\\textcolor{#0b4f8a}{%1}").arg(result);
    return parts.join(QStringLiteral(" = "));
}

QString inlineMathHtml(const QString& latex)
{
    return QStringLiteral("<span class=\"tex\">%1</span>").arg(htmlEscape(texExponents(latex)));
}

QString displayMathHtml(const QString& latex)
{
    return rowHtml(latex);
}

QString missingLatex(const QString& what, const QString& reason)
{
    return QStringLiteral("\\textcolor{#b3261e}{\\text{[%1: %2]}}").arg(latexTextEscape(what), latexTextEscape(reason));
}

QString missingHtml(const QString& what, const QString& reason)
{
    return QStringLiteral("<span class=\"missing\">[%1: %2]</span>").arg(htmlEscape(what), htmlEscape(reason));
}

} // namespace rbw
