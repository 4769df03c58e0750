// A derivation as one self-contained HTML file: the already rendered page (KaTeX's
// HTML output) with katex.min.css inlined and its fonts embedded as data: URLs
// (woff2). It needs no script and no other file, so it opens offline anywhere.
#pragma once

#include <QString>

namespace rbw {

// katex.min.css from katexDir (a local folder, e.g. /usr/share/javascript/katex) with
// every @font-face reduced to its woff2 file as a base64 data: URL. Empty and *error
// set if the style sheet or a font cannot be read.
QString inlinedKatexCss(const QString& katexDir, QString* error);

// The document: <!DOCTYPE html>, the inlined KaTeX CSS, the page CSS
// (derivationCss()), and renderedBodyHtml (the inner HTML of <body> after rendering)
// with any <script> element removed.
QString standaloneDerivationHtml(const QString& renderedBodyHtml, const QString& title, const QString& katexDir,
                                 QString* error);

} // namespace rbw
