// The HTML page a derivation is shown in: the document skeleton (standards mode,
// KaTeX from the Debian package, the render script that reports its counts), the
// style sheet, and the small HTML/LaTeX building blocks the builder and the
// fallback share. Formatting only: no numbers are made here.
#pragma once

#include <QString>
#include <QStringList>

namespace rbw {

// file:///usr/share/javascript/katex/ (Debian's libjs-katex), with the trailing slash.
QString defaultKatexUrl();

// The page's own style sheet (typography, numbered sections, rows).
QString derivationCss();

// A complete document, starting with <!DOCTYPE html>. The math is in elements of class
// "tex" (plus "display" for display math) holding the LaTeX as text; the script
// renders each with katex.render (throwOnError: false, so a bad formula becomes a
// .katex-error span) and, after document.fonts.ready, sets
// window.rbwRender = {katex: <count of .katex>, errors: <count of .katex-error>}.
QString derivationPage(const QString& bodyHtml, const QString& title, const QString& katexUrl = defaultKatexUrl());

QString htmlEscape(const QString& text);
// Text for \text{...}: escapes LaTeX's special characters.
QString latexTextEscape(const QString& text);
// "kg·m²/s" -> "\mathrm{kg\cdot m^{2}/s}"; empty for an empty unit.
QString unitLatex(const QString& unit);

// One derivation row as LaTeX: an aligned environment, formula on the first line,
// "= substituted" and "= result" below it, aligned at the formula's first top-level
// relation (=, \leftarrow, \approx). Empty cells are left out.
QString rowLatex(const QString& formula, const QString& substituted, const QString& result);

// The same row on one line: "formula = substituted = result".
QString rowInlineLatex(const QString& formula, const QString& substituted, const QString& result);

// A number in e-notation as a power of ten: "2.86e-17" becomes 2.86 \cdot 10^{-17}
// (KaTeX would typeset "2.86e − 17"). rowHtml and inlineMathHtml apply it.
QString texExponents(const QString& latex);

// <div class="row"><div class="tex display" data-inline="...">stacked</div></div>: the
// page shows the one-line form where it fits the width and the stacked form where not
// (and again after a resize). Without inlineLatex the row is always stacked.
QString rowHtml(const QString& latex, const QString& inlineLatex = QString());
// Inline math: <span class="tex">...</span>.
QString inlineMathHtml(const QString& latex);
// Display math: <div class="row"><div class="tex display">...</div></div>.
QString displayMathHtml(const QString& latex);

// The note shown instead of a value that is not in the trace, in LaTeX and in HTML.
QString missingLatex(const QString& what, const QString& reason);
QString missingHtml(const QString& what, const QString& reason);

} // namespace rbw
